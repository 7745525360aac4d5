#pragma once

#include <string>
#include <vector>

namespace brick_stack_sim {

/// Minimal streaming JSON writer: commas and escapes are its whole job. Numbers
/// are written with 17 significant digits so equal reports mean equal bits;
/// NaN and Inf, which JSON cannot hold, become null.
class JsonWriter {
 public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(const std::string& name);
  JsonWriter& value(const std::string& text);
  JsonWriter& value(const char* text) { return value(std::string(text)); }
  JsonWriter& value(double number);
  JsonWriter& value(unsigned long long number);
  JsonWriter& value(bool flag);
  JsonWriter& null();  ///< JSON's null: a value that is not there (a time that never came).
  JsonWriter& numbers(const double* data, int count);
  const std::string& str() const { return out_; }

 private:
  void separate();
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written in it yet
  bool after_key_ = false;
};

}  // namespace brick_stack_sim
