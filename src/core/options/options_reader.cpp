#include "brick_stack_sim/core/options/options_reader.h"

#include <algorithm>

#include <limits>
#include <utility>

namespace brick_stack_sim {

namespace {

/// Keys this many edits from a known one get it suggested.
constexpr std::size_t kMaxSuggestionDistance = 2;

/// Levenshtein distance; long keys are not worth the quadratic cost.
std::size_t editDistance(const std::string& a, const std::string& b) {
  if (a.size() > 64 || b.size() > 64) return kMaxSuggestionDistance + 1;
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// How many known keys an unknown-key message lists before "...".
constexpr std::size_t kMaxListedKeys = 20;

/// "table/" -> "table".
std::string withoutTrailingSlash(std::string path) {
  if (!path.empty() && path.back() == '/') path.pop_back();
  return path;
}

}  // namespace

OptionsReader::OptionsReader(const ParameterValue& values, std::string path)
    : values_(&values), path_(std::move(path)) {
  if (!values_->isMap()) {
    const std::string where =
        path_.empty() ? "the parameters are" : withoutTrailingSlash(path_) + " is";
    error_ = Status::error(where + " " + values_->describe() + ", expected a map");
  }
}

const std::string& OptionsReader::path() const { return path_; }

const ParameterValue& OptionsReader::values() const { return *values_; }

const ParameterValue* OptionsReader::lookUp(const std::string& key) {
  known_.insert(key);
  if (!error_.ok) return nullptr;
  return values_->find(key);
}

void OptionsReader::wrongType(const std::string& name, const ParameterValue& found,
                              const std::string& expected) {
  fail(Status::error(path_ + name + " is " + found.describe() + ", expected " + expected));
}

void OptionsReader::read(const std::string& key, double* value) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isNumber()) return wrongType(key, *found, "a number");
  *value = found->asDouble();
}

void OptionsReader::read(const std::string& key, int* value) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isInt()) return wrongType(key, *found, "an integer");
  const long long number = found->asInt();
  if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max()) {
    return wrongType(key, *found,
                     "an integer from " + std::to_string(std::numeric_limits<int>::min()) + " to " +
                         std::to_string(std::numeric_limits<int>::max()));
  }
  *value = static_cast<int>(number);
}

void OptionsReader::read(const std::string& key, bool* value) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isBool()) return wrongType(key, *found, "a bool");
  *value = found->asBool();
}

void OptionsReader::read(const std::string& key, std::string* value) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isString()) return wrongType(key, *found, "a string");
  *value = found->asString();
}

bool OptionsReader::readNumbers(const std::string& key, int size, std::vector<double>* numbers) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return false;
  const std::string expected =
      size < 0 ? "a list of numbers" : "a list of " + std::to_string(size) + " numbers";
  if (!found->isList() || (size >= 0 && found->list().size() != static_cast<std::size_t>(size))) {
    wrongType(key, *found, expected);
    return false;
  }
  const ParameterValue::List& items = found->list();
  numbers->clear();
  numbers->reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].isNumber()) {
      wrongType(key + "[" + std::to_string(i) + "]", items[i], "a number");
      return false;
    }
    numbers->push_back(items[i].asDouble());
  }
  return true;
}

void OptionsReader::read(const std::string& key, std::vector<double>* value) {
  std::vector<double> numbers;
  if (readNumbers(key, -1, &numbers)) *value = std::move(numbers);
}

void OptionsReader::read(const std::string& key, std::vector<std::string>* value) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isList()) return wrongType(key, *found, "a list of strings");
  std::vector<std::string> strings;
  strings.reserve(found->list().size());
  for (std::size_t i = 0; i < found->list().size(); ++i) {
    const ParameterValue& item = found->list()[i];
    if (!item.isString()) return wrongType(key + "[" + std::to_string(i) + "]", item, "a string");
    strings.push_back(item.asString());
  }
  *value = std::move(strings);
}

void OptionsReader::read(const std::string& key, Eigen::Vector2d* value) {
  std::vector<double> numbers;
  if (readNumbers(key, 2, &numbers)) *value = Eigen::Vector2d(numbers[0], numbers[1]);
}

void OptionsReader::read(const std::string& key, Eigen::Vector3d* value) {
  std::vector<double> numbers;
  if (readNumbers(key, 3, &numbers)) *value = Eigen::Vector3d(numbers[0], numbers[1], numbers[2]);
}

void OptionsReader::section(const std::string& key,
                            const std::function<Status(OptionsReader&)>& read_section) {
  const ParameterValue* found = lookUp(key);
  if (found == nullptr) return;
  if (!found->isMap()) return wrongType(key, *found, "a map");
  OptionsReader reader(*found, path_ + key + "/");
  Status status = read_section ? read_section(reader) : Status::success();
  if (status.ok) status = reader.finish();
  fail(status);
}

void OptionsReader::skip(const std::string& key) { known_.insert(key); }

void OptionsReader::fail(const Status& error) {
  if (error_.ok && !error.ok) error_ = error;
}

Status OptionsReader::named(const Status& status) const {
  if (status.ok) return status;
  return Status::error(path_ + status.message);
}

bool OptionsReader::ok() const { return error_.ok; }

Status OptionsReader::finish() const {
  if (!error_.ok) return error_;
  for (const auto& member : values_->map()) {
    if (known_.count(member.first) != 0) continue;
    // A typo is most often a letter or two off a known key: name that one first.
    std::string closest;
    std::size_t closest_distance = kMaxSuggestionDistance + 1;
    for (const std::string& name : known_) {
      const std::size_t distance = editDistance(member.first, name);
      if (distance < closest_distance) {
        closest = name;
        closest_distance = distance;
      }
    }
    const std::string suggestion = closest.empty() ? "" : "did you mean " + path_ + closest + "? ";
    std::string known;
    std::size_t listed = 0;
    for (const std::string& name : known_) {
      if (listed == kMaxListedKeys) {
        known += ", ...";
        break;
      }
      if (listed++ > 0) known += ", ";
      known += name;
    }
    if (known.empty()) known = "none";
    return Status::error(path_ + shortenForMessage(member.first) + " is not a known parameter (" +
                         suggestion + "known here: " + known + ")");
  }
  return Status::success();
}

}  // namespace brick_stack_sim
