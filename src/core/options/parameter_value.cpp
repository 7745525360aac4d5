#include "brick_stack_sim/core/options/parameter_value.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <system_error>

namespace brick_stack_sim {

namespace {

/// Longest string describe() echoes in full [bytes].
constexpr std::size_t kMaxDescribedString = 60;

/// Index of the first member whose key is not less than `key`.
template <typename MapType>
auto lowerBound(MapType& map, const std::string& key) {
  return std::lower_bound(
      map.begin(), map.end(), key,
      [](const auto& member, const std::string& k) { return member.first < k; });
}

/// The shortest text that reads back as `value` ("0.5", "3", "1e-05", "inf").
std::string formatDouble(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  if (result.ec != std::errc()) return "?";
  return std::string(buffer, result.ptr);
}

}  // namespace

ParameterValue::ParameterValue() : value_(Map{}) {}

ParameterValue::ParameterValue(Variant value) : value_(std::move(value)) {}

ParameterValue ParameterValue::makeBool(bool value) { return ParameterValue(Variant(value)); }

ParameterValue ParameterValue::makeInt(long long value) { return ParameterValue(Variant(value)); }

ParameterValue ParameterValue::makeDouble(double value) { return ParameterValue(Variant(value)); }

ParameterValue ParameterValue::makeString(std::string value) {
  return ParameterValue(Variant(std::move(value)));
}

ParameterValue ParameterValue::makeList(List items) {
  return ParameterValue(Variant(std::move(items)));
}

ParameterValue ParameterValue::makeMap() { return ParameterValue(); }

ParameterValue::Type ParameterValue::type() const {
  switch (value_.index()) {
    case 0:
      return Type::kBool;
    case 1:
      return Type::kInt;
    case 2:
      return Type::kDouble;
    case 3:
      return Type::kString;
    case 4:
      return Type::kList;
    default:
      return Type::kMap;
  }
}

bool ParameterValue::isBool() const { return std::holds_alternative<bool>(value_); }
bool ParameterValue::isInt() const { return std::holds_alternative<long long>(value_); }
bool ParameterValue::isDouble() const { return std::holds_alternative<double>(value_); }
bool ParameterValue::isNumber() const { return isInt() || isDouble(); }
bool ParameterValue::isString() const { return std::holds_alternative<std::string>(value_); }
bool ParameterValue::isList() const { return std::holds_alternative<List>(value_); }
bool ParameterValue::isMap() const { return std::holds_alternative<Map>(value_); }

bool ParameterValue::asBool() const {
  assert(isBool());
  const bool* value = std::get_if<bool>(&value_);
  return value != nullptr && *value;
}

long long ParameterValue::asInt() const {
  assert(isInt());
  const long long* value = std::get_if<long long>(&value_);
  return value != nullptr ? *value : 0;
}

double ParameterValue::asDouble() const {
  assert(isNumber());
  if (const double* value = std::get_if<double>(&value_)) return *value;
  if (const long long* value = std::get_if<long long>(&value_)) return static_cast<double>(*value);
  return 0.0;
}

const std::string& ParameterValue::asString() const {
  assert(isString());
  static const std::string kEmpty;
  const std::string* value = std::get_if<std::string>(&value_);
  return value != nullptr ? *value : kEmpty;
}

const ParameterValue::List& ParameterValue::list() const {
  assert(isList());
  static const List kEmpty;
  const List* value = std::get_if<List>(&value_);
  return value != nullptr ? *value : kEmpty;
}

const ParameterValue::Map& ParameterValue::map() const {
  assert(isMap());
  static const Map kEmpty;
  const Map* value = std::get_if<Map>(&value_);
  return value != nullptr ? *value : kEmpty;
}

const ParameterValue* ParameterValue::find(const std::string& key) const {
  const Map* map = std::get_if<Map>(&value_);
  if (map == nullptr) return nullptr;
  const auto it = lowerBound(*map, key);
  if (it == map->end() || it->first != key) return nullptr;
  return &it->second;
}

ParameterValue* ParameterValue::findMutable(const std::string& key) {
  return const_cast<ParameterValue*>(static_cast<const ParameterValue*>(this)->find(key));
}

void ParameterValue::set(const std::string& key, ParameterValue value) {
  if (!isMap()) value_ = Map{};
  Map& map = std::get<Map>(value_);
  const auto it = lowerBound(map, key);
  if (it != map.end() && it->first == key) {
    it->second = std::move(value);
  } else {
    map.emplace(it, key, std::move(value));
  }
}

void ParameterValue::setPath(const std::string& path, ParameterValue value) {
  std::vector<std::string> keys;
  std::size_t begin = 0;
  while (begin <= path.size()) {
    std::size_t end = path.find('/', begin);
    if (end == std::string::npos) end = path.size();
    if (end > begin) keys.push_back(path.substr(begin, end - begin));
    begin = end + 1;
  }
  if (keys.empty()) {
    *this = std::move(value);
    return;
  }
  ParameterValue* node = this;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    ParameterValue* member = node->findMutable(keys[i]);
    if (member == nullptr || !member->isMap()) {
      node->set(keys[i], makeMap());
      member = node->findMutable(keys[i]);
    }
    node = member;
  }
  node->set(keys.back(), std::move(value));
}

void ParameterValue::merge(const ParameterValue& other) {
  // A copy first: `other` may sit inside this tree, and merging moves members around.
  ParameterValue copy = other;
  mergeMoved(std::move(copy));
}

void ParameterValue::mergeMoved(ParameterValue&& other) {
  if (!isMap() || !other.isMap()) {
    value_ = std::move(other.value_);
    return;
  }
  for (auto& [key, member] : std::get<Map>(other.value_)) {
    if (ParameterValue* mine = findMutable(key)) {
      mine->mergeMoved(std::move(member));
    } else {
      set(key, std::move(member));
    }
  }
}

std::string ParameterValue::describe() const {
  switch (type()) {
    case Type::kBool:
      return asBool() ? "bool true" : "bool false";
    case Type::kInt:
      return "int " + std::to_string(asInt());
    case Type::kDouble:
      return "double " + formatDouble(asDouble());
    case Type::kString: {
      const std::string& text = asString();
      std::string described = "string '" + shortenForMessage(text, kMaxDescribedString) + "'";
      if (text.size() > kMaxDescribedString)
        described += " (" + std::to_string(text.size()) + " characters)";
      return described;
    }
    case Type::kList:
      return "a list of " + std::to_string(list().size());
    case Type::kMap:
      break;
  }
  return "a map";
}

bool ParameterValue::operator==(const ParameterValue& other) const {
  return value_ == other.value_;
}

std::string shortenForMessage(const std::string& text, std::size_t max_bytes) {
  std::size_t end = text.size();
  const bool cut = end > max_bytes;
  if (cut) {
    end = max_bytes;
    // Back to the start of a UTF-8 sequence (continuation bytes are 10xxxxxx).
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u) --end;
  }
  std::string shortened;
  shortened.reserve(end + 3);
  for (std::size_t i = 0; i < end; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      shortened += "\\n";
    } else if (c == '\t') {
      shortened += "\\t";
    } else if (c == '\r') {
      shortened += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      static const char kHex[] = "0123456789abcdef";
      shortened += "\\x";
      shortened += kHex[c >> 4];
      shortened += kHex[c & 0xFu];
    } else {
      shortened += static_cast<char>(c);
    }
  }
  if (cut) shortened += "...";
  return shortened;
}

}  // namespace brick_stack_sim
