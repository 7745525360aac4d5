#include "brick_stack_sim/core/options/yaml_parameters.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace brick_stack_sim {

namespace {

/// Deeper nesting is refused: no configuration needs it, and yaml-cpp turns an alias to its own
/// ancestor (`a: &x [*x]`) into a cycle that would otherwise recurse without end.
constexpr int kMaxDepth = 100;

/// More values are refused: aliases let a small file expand exponentially ("billion laughs").
constexpr std::size_t kMaxValues = 1000000;

const char kTagStr[] = "tag:yaml.org,2002:str";
const char kTagInt[] = "tag:yaml.org,2002:int";
const char kTagFloat[] = "tag:yaml.org,2002:float";
const char kTagBool[] = "tag:yaml.org,2002:bool";

bool equalsIgnoringCase(const std::string& text, const char* word) {
  const std::size_t length = std::strlen(word);
  if (text.size() != length) return false;
  for (std::size_t i = 0; i < length; ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) != word[i]) return false;
  }
  return true;
}

/// YAML 1.1 booleans, in any case.
bool parseBool(const std::string& text, bool* value) {
  for (const char* word : {"true", "yes", "on"}) {
    if (equalsIgnoringCase(text, word)) return *value = true, true;
  }
  for (const char* word : {"false", "no", "off"}) {
    if (equalsIgnoringCase(text, word)) return *value = false, true;
  }
  return false;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// Skips digits from `*i`; returns how many.
std::size_t skipDigits(const std::string& text, std::size_t* i) {
  const std::size_t begin = *i;
  while (*i < text.size() && isDigit(text[*i])) ++*i;
  return *i - begin;
}

/// [-+]?[0-9]+
bool isDecimalInteger(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
  return skipDigits(text, &i) > 0 && i == text.size();
}

/// [-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)? -- scanned by hand: std::regex recurses per
/// character and a long scalar would overflow the stack.
bool isDecimalFloat(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
  std::size_t digits = skipDigits(text, &i);
  if (i < text.size() && text[i] == '.') {
    ++i;
    digits += skipDigits(text, &i);
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    if (skipDigits(text, &i) == 0) return false;
  }
  return i == text.size();
}

/// .inf, +.inf, -.inf, .nan in any case.
bool parseSpecialFloat(const std::string& text, double* value) {
  std::size_t i = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
  const std::string rest = text.substr(i);
  if (equalsIgnoringCase(rest, ".inf")) {
    *value = text[0] == '-' ? -std::numeric_limits<double>::infinity()
                            : std::numeric_limits<double>::infinity();
    return true;
  }
  if (i == 0 && equalsIgnoringCase(rest, ".nan")) {
    *value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  return false;
}

/// Builds a tree from yaml-cpp's nodes, remembering the first error.
class Converter {
 public:
  explicit Converter(std::string source) : source_(std::move(source)) {}

  const Status& status() const { return status_; }

  /// Converts `node`, whose path is `path` ("" at the top), found at `mark` (for a null, whose own
  /// mark yaml-cpp puts on the following line, the mark of its key).
  bool convert(const YAML::Node& node, const std::string& path, const YAML::Mark& mark, int depth,
               ParameterValue* value) {
    if (depth > kMaxDepth) {
      return fail(mark, shortenForMessage(path, 200) + " is nested more than " +
                            std::to_string(kMaxDepth) + " levels deep");
    }
    if (++values_ > kMaxValues) {
      return fail(mark, "the document holds more than " + std::to_string(kMaxValues) +
                            " values (aliases expanding?)");
    }
    switch (node.Type()) {
      case YAML::NodeType::Scalar:
        return convertScalar(node, path, value);
      case YAML::NodeType::Sequence: {
        ParameterValue::List items;
        items.reserve(node.size());
        for (const YAML::Node& item : node) {
          ParameterValue converted;
          const std::string item_path = path + "[" + std::to_string(items.size()) + "]";
          if (!convert(item, item_path, item.Mark(), depth + 1, &converted)) return false;
          items.push_back(std::move(converted));
        }
        *value = ParameterValue::makeList(std::move(items));
        return true;
      }
      case YAML::NodeType::Map:
        return convertMap(node, path, depth, value);
      case YAML::NodeType::Null:
      case YAML::NodeType::Undefined:
        break;
    }
    return fail(mark, (path.empty() ? std::string("a value") : path) + " has no value");
  }

 private:
  bool fail(const YAML::Mark& mark, const std::string& message) {
    std::string where = source_;
    if (!mark.is_null())
      where += (where.empty() ? "line " : " line ") + std::to_string(mark.line + 1);
    status_ = Status::error(where.empty() ? message : where + ": " + message);
    return false;
  }

  bool convertMap(const YAML::Node& node, const std::string& path, int depth,
                  ParameterValue* value) {
    ParameterValue map = ParameterValue::makeMap();
    std::set<std::string> seen;
    const std::string in = path.empty() ? std::string("the top of the document") : path;
    for (const auto& entry : node) {  // not it->first: operator-> returns a temporary proxy
      const YAML::Node& key = entry.first;
      if (!key.IsScalar()) return fail(key.Mark(), in + " has a key that is not a plain name");
      const std::string& name = key.Scalar();
      const std::string shown = shortenForMessage(name);
      if (name.empty()) return fail(key.Mark(), in + " has an empty key");
      if (name.find('/') != std::string::npos) {
        return fail(key.Mark(), in + " has the key '" + shown +
                                    "' with a '/' in it; write nested maps instead");
      }
      const std::string member_path = path.empty() ? shown : path + "/" + shown;
      if (!seen.insert(name).second) return fail(key.Mark(), member_path + " is given twice");
      ParameterValue member;
      if (!convert(entry.second, member_path, key.Mark(), depth + 1, &member)) return false;
      map.set(name, std::move(member));
    }
    *value = std::move(map);
    return true;
  }

  bool convertScalar(const YAML::Node& node, const std::string& path, ParameterValue* value) {
    const std::string& tag = node.Tag();
    const std::string& text = node.Scalar();
    if (tag == "!" || tag == kTagStr) {  // "!": quoted or block scalar
      *value = ParameterValue::makeString(text);
      return true;
    }
    if (tag != "?" && tag != kTagInt && tag != kTagFloat && tag != kTagBool) {
      return fail(node.Mark(), path + " has the yaml tag '" + shortenForMessage(tag) +
                                   "', which is not supported");
    }
    ParameterValue resolved;
    if (!resolvePlain(node, path, &resolved)) return false;
    const bool fits = tag == "?" || (tag == kTagInt && resolved.isInt()) ||
                      (tag == kTagFloat && resolved.isNumber()) ||
                      (tag == kTagBool && resolved.isBool());
    if (!fits) {
      return fail(node.Mark(), path + " = '" + shortenForMessage(text) + "' does not fit its tag " +
                                   tag.substr(tag.rfind(':') + 1));
    }
    if (tag == kTagFloat) resolved = ParameterValue::makeDouble(resolved.asDouble());
    *value = std::move(resolved);
    return true;
  }

  /// Types a plain scalar as YAML 1.1 (rosparam) does.
  bool resolvePlain(const YAML::Node& node, const std::string& path, ParameterValue* value) {
    const std::string& text = node.Scalar();
    bool flag = false;
    double number = 0.0;
    if (parseBool(text, &flag)) {
      *value = ParameterValue::makeBool(flag);
      return true;
    }
    if (parseSpecialFloat(text, &number)) {
      *value = ParameterValue::makeDouble(number);
      return true;
    }
    // from_chars takes no '+'.
    const std::size_t skip = (!text.empty() && text[0] == '+') ? 1 : 0;
    const char* begin = text.data() + skip;
    const char* end = text.data() + text.size();
    if (isDecimalInteger(text)) {
      long long integer = 0;
      const std::from_chars_result result = std::from_chars(begin, end, integer);
      if (result.ec == std::errc() && result.ptr == end) {
        *value = ParameterValue::makeInt(integer);
        return true;
      }
      // Out of the range of long long: a double, as the spec of rosparam's types says.
    }
    if (isDecimalInteger(text) || isDecimalFloat(text)) {
      const std::from_chars_result result = std::from_chars(begin, end, number);
      if (result.ec != std::errc() || result.ptr != end) {
        return fail(node.Mark(),
                    path + " = " + shortenForMessage(text) + " is out of the range of a double");
      }
      *value = ParameterValue::makeDouble(number);
      return true;
    }
    *value = ParameterValue::makeString(text);
    return true;
  }

  std::string source_;
  Status status_;
  std::size_t values_ = 0;
};

/// "no such file" rather than strerror's "No such file or directory": reads better after a colon.
std::string describeErrno(int error) {
  switch (error) {
    case ENOENT:
    case ENOTDIR:
      return "no such file";
    case EACCES:
      return "permission denied";
    default:
      break;
  }
  std::string text = std::strerror(error);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

}  // namespace

Status parseYamlParameters(const std::string& text, const std::string& source,
                           ParameterValue* value) {
  const std::string subject = source.empty() ? std::string("the text") : source;
  try {
    const std::vector<YAML::Node> documents = YAML::LoadAll(text);
    if (documents.size() > 1) {
      return Status::error(subject + " holds " + std::to_string(documents.size()) +
                           " yaml documents, expected one");
    }
    if (documents.empty() || documents[0].IsNull()) {
      *value = ParameterValue::makeMap();
      return Status::success();
    }
    Converter converter(source);
    ParameterValue tree;
    if (!converter.convert(documents[0], "", documents[0].Mark(), 0, &tree)) {
      return converter.status();
    }
    if (!tree.isMap()) {
      return Status::error((source.empty() ? std::string() : source + ": ") +
                           "the top of the document is " + tree.describe() + ", expected a map");
    }
    *value = std::move(tree);
    return Status::success();
  } catch (const YAML::Exception& e) {
    std::string where = subject;
    if (!e.mark.is_null()) where += " line " + std::to_string(e.mark.line + 1);
    return Status::error(where + ": invalid yaml: " + e.msg);
  } catch (const std::exception& e) {
    return Status::error(subject + ": could not be parsed: " + e.what());
  }
}

Status loadYamlParameters(const std::string& path, ParameterValue* value, std::size_t max_bytes) {
  const std::string name = "config '" + path + "'";
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    return Status::error("cannot read " + name + ": " + describeErrno(errno));
  }
  if (!S_ISREG(info.st_mode)) return Status::error(name + " is not a regular file");
  if (static_cast<unsigned long long>(info.st_size) > max_bytes) {
    return Status::error(name + " is " + std::to_string(info.st_size) +
                         " bytes, more than the limit of " + std::to_string(max_bytes));
  }
  // O_NONBLOCK: should the path have been swapped for a FIFO since stat(), open() must not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) return Status::error("cannot read " + name + ": " + describeErrno(errno));
  struct stat opened {};
  if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
    ::close(fd);
    return Status::error(name + " is not a regular file");
  }
  // Read at most max_bytes + 1: one byte more than allowed tells that the file grew.
  const std::size_t limit =
      max_bytes < std::numeric_limits<std::size_t>::max() ? max_bytes + 1 : max_bytes;
  std::string text;
  text.resize(std::min<std::size_t>(limit, static_cast<std::size_t>(opened.st_size) + 1));
  std::size_t size = 0;
  while (size < limit) {
    if (size == text.size()) text.resize(std::min(limit, text.size() * 2 + 4096));
    const ssize_t got = ::read(fd, &text[size], text.size() - size);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int error = errno;
      ::close(fd);
      return Status::error("cannot read " + name + ": " + describeErrno(error));
    }
    if (got == 0) break;
    size += static_cast<std::size_t>(got);
  }
  ::close(fd);
  if (size > max_bytes) {
    // It grew since stat(), or stat() does not know its size (procfs).
    return Status::error(name + " is more than the limit of " + std::to_string(max_bytes) +
                         " bytes");
  }
  text.resize(size);
  return parseYamlParameters(text, path, value);
}

}  // namespace brick_stack_sim
