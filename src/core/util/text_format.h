#pragma once
// How the core writes numbers into the messages and reasons people read.

#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace brick_stack_sim {

/// "(x, y, z)" with six significant digits.
inline std::string formatVector(const Eigen::Vector3d& v) {
  std::ostringstream text;
  text.precision(6);
  text << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return text.str();
}

/// A number as printf's %g writes it: six significant digits and no
/// trailing zeros ("50", "0.0039", "1e+06"), never "1000000.000000".
inline std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// A length given in metres, written in millimetres: "1.25 mm".
inline std::string millimetres(double metres) {
  std::ostringstream text;
  text.precision(3);
  text << metres * 1000.0 << " mm";
  return text.str();
}

/// A fraction written as a percentage: "12.5 %".
inline std::string percent(double fraction) {
  std::ostringstream text;
  text.precision(3);
  text << fraction * 100.0 << " %";
  return text.str();
}

/// A force [N]: "0.115 N".
inline std::string newtons(double force) {
  std::ostringstream text;
  text.precision(3);
  text << force << " N";
  return text.str();
}

/// An energy [J], written in millijoules: "1.49 mJ".
inline std::string millijoules(double joules) {
  std::ostringstream text;
  text.precision(3);
  text << joules * 1000.0 << " mJ";
  return text.str();
}

/// Longest id a message repeats in full [characters]; longer ones are cut.
constexpr std::size_t kQuotedIdLength = 40;

/// `text` as messages show it, in quotes: in full up to `max_length`
/// characters, else its start and its length ('abc...' (10240 characters)),
/// so that a refusal never echoes a huge request back, nor logs it.
inline std::string quotedText(const std::string& text, std::size_t max_length) {
  if (text.size() <= max_length) return "'" + text + "'";
  return "'" + text.substr(0, max_length) + "...' (" + std::to_string(text.size()) + " characters)";
}
/// An id as messages show it: quotedText() up to kQuotedIdLength.
inline std::string quotedId(const std::string& id) { return quotedText(id, kQuotedIdLength); }

/// Longest path or scene name a message repeats in full [characters].
constexpr std::size_t kQuotedPathLength = 200;

/// `text` as messages show it, unquoted: in full up to `max_length`
/// characters, else its start and its length ("/tmp/aaa... (10240
/// characters)"), so that a refusal never echoes a huge request back.
inline std::string shortText(const std::string& text, std::size_t max_length = kQuotedPathLength) {
  if (text.size() <= max_length) return text;
  return text.substr(0, max_length) + "... (" + std::to_string(text.size()) + " characters)";
}

/// A path or scene name as messages show it: quotedText() up to kQuotedPathLength.
inline std::string quotedPath(const std::string& path) {
  return quotedText(path, kQuotedPathLength);
}

/// "a, b, c".
inline std::string joinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace brick_stack_sim
