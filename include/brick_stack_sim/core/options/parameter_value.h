#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace brick_stack_sim {

/// One value of a parameter tree, as a yaml file or the ROS parameter server holds it.
///
/// The options of every module are read from such a tree, whichever of the two it came from, so
/// that type checks, messages and the refusal of unknown keys are the same in the batch runner and
/// in the node. Accessors of the wrong type never throw: they are preconditions, checked by an
/// assert in debug builds and answered with false, 0 or an empty value otherwise.
class ParameterValue {
 public:
  enum class Type { kBool, kInt, kDouble, kString, kList, kMap };
  using List = std::vector<ParameterValue>;
  /// Sorted by key, keys unique: std::map cannot hold the incomplete ParameterValue.
  using Map = std::vector<std::pair<std::string, ParameterValue>>;

  /// An empty map: the tree of a file or namespace without parameters.
  ParameterValue();

  static ParameterValue makeBool(bool value);
  static ParameterValue makeInt(long long value);
  static ParameterValue makeDouble(double value);
  static ParameterValue makeString(std::string value);
  static ParameterValue makeList(List items);
  /// An empty map.
  static ParameterValue makeMap();

  Type type() const;
  bool isBool() const;
  bool isInt() const;
  bool isDouble() const;
  /// An int or a double: YAML writes 10 for 10.0, so both are numbers.
  bool isNumber() const;
  bool isString() const;
  bool isList() const;
  bool isMap() const;

  /// Precondition: isBool().
  bool asBool() const;
  /// Precondition: isInt().
  long long asInt() const;
  /// Precondition: isNumber(); an int is converted.
  double asDouble() const;
  /// Precondition: isString().
  const std::string& asString() const;
  /// Precondition: isList().
  const List& list() const;
  /// Precondition: isMap().
  const Map& map() const;

  /// A member of a map; nullptr when absent or when this is not a map.
  const ParameterValue* find(const std::string& key) const;

  /// Sets a member of a map, replacing one with the same key. This must be a map; a value of
  /// another type is replaced by an empty map first, so the call never has undefined behaviour.
  void set(const std::string& key, ParameterValue value);

  /// Sets by slash-separated path ("table/size"), creating maps on the way and replacing non-maps
  /// on the way. Empty components ("a//b", "/a") are skipped; a path without any component
  /// replaces this whole value. For tests and command-line overrides.
  void setPath(const std::string& path, ParameterValue value);

  /// Merges `other` into this: two maps merge member by member, recursively; anything else is
  /// replaced by `other`. Later files win, as `rosparam load` of two files into one namespace does.
  /// `other` may be a part of this tree.
  void merge(const ParameterValue& other);

  /// For messages: "bool true", "int 3", "double 0.5", "string 'abc'", "a list of 3", "a map".
  /// A string longer than 60 characters is cut with "..." and its length added
  /// ("string 'aaa...' (10000 characters)"), so a message never echoes a huge value.
  std::string describe() const;

  /// Same type and same value, recursively (a double NaN equals nothing). Mostly for tests.
  bool operator==(const ParameterValue& other) const;
  bool operator!=(const ParameterValue& other) const { return !(*this == other); }

 private:
  using Variant = std::variant<bool, long long, double, std::string, List, Map>;
  explicit ParameterValue(Variant value);

  ParameterValue* findMutable(const std::string& key);
  void mergeMoved(ParameterValue&& other);

  Variant value_;
};

/// `text` made safe to put in a message: control characters escaped ("\n", "\x01"), cut after
/// `max_bytes` bytes (not inside a UTF-8 sequence) with "..." appended. Keys and strings of a
/// parameter tree come from users and may be arbitrarily long.
std::string shortenForMessage(const std::string& text, std::size_t max_bytes = 60);

}  // namespace brick_stack_sim
