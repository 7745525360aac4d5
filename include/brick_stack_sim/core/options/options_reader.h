#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// Reads one map of a parameter tree into an options struct, key by key, and
/// remembers which keys were read, so that finish() can refuse a key nobody
/// knows. Messages name keys by their path in the tree ("table/size"); the
/// caller puts its own prefix in front ("parameter ~" in the node, the file
/// name in the runner).
///
/// Each module reads its own section (cartographer's Create...Options style):
/// \code
/// Status readTableOptions(OptionsReader& reader, TableOptions* table) {
///   TableOptions t = *table;
///   reader.read("size", &t.size);
///   reader.read("thickness", &t.thickness);
///   if (Status done = reader.finish(); !done) return done;
///   if (Status valid = validate(t); !valid) return reader.named(valid);
///   *table = t;
///   return Status::success();
/// }
/// // In the parent: reader.section("table", &readTableOptions, &world.table);
/// \endcode
class OptionsReader {
 public:
  /// `values` must outlive the reader. `path` is where the map sits in the tree: "" at the root,
  /// "table/" below it. When `values` is not a map, that is the reader's first error.
  explicit OptionsReader(const ParameterValue& values, std::string path = "");

  const std::string& path() const;
  /// The map being read, for a module whose keys are names chosen by the user (one section per
  /// brick type, say): it walks values().map() and calls section() or skip() for each key.
  const ParameterValue& values() const;

  // Each read sets *value when `key` is present and of the right type; when absent, *value keeps
  // its default. A wrong type is an error naming path+key and the value found ("time_step is
  // string 'fast', expected a number") and leaves *value alone. After the first error every
  // further call does nothing: the first error is the one reported.

  /// An int is accepted: YAML writes 10 for 10.0.
  void read(const std::string& key, double* value);
  /// An int only (a double is not truncated), within the range of int.
  void read(const std::string& key, int* value);
  /// A bool only: "true" as a string or 1 as an int are wrong types.
  void read(const std::string& key, bool* value);
  void read(const std::string& key, std::string* value);
  /// Each item a number; a message names the item ("table/size[1] is string 'wide', expected a
  /// number").
  void read(const std::string& key, std::vector<double>* value);
  /// Each item a string.
  void read(const std::string& key, std::vector<std::string>* value);
  /// A list of exactly 2 numbers ("table/size is a list of 3, expected a list of 2 numbers").
  void read(const std::string& key, Eigen::Vector2d* value);
  /// A list of exactly 3 numbers.
  void read(const std::string& key, Eigen::Vector3d* value);

  /// Reads the map under `key` with `read_section(reader_of_that_map, options)`; that reader's
  /// path is path() + key + "/". Absent key: nothing is called, the defaults stay. Present but not
  /// a map: error "sleeping is double 3, expected a map". An error returned by read_section
  /// becomes this reader's error; when read_section returns success, the section's own finish()
  /// is checked as well, so a module that forgets to call it cannot let an unknown key through.
  /// The key counts as read.
  template <typename Options>
  void section(const std::string& key, Status (*read_section)(OptionsReader&, Options*),
               Options* options) {
    section(key, [read_section, options](OptionsReader& reader) {
      return read_section(reader, options);
    });
  }

  /// As above, for any callable that reads the section (a lambda capturing what it fills).
  void section(const std::string& key, const std::function<Status(OptionsReader&)>& read_section);

  /// Marks `key` as known although nothing here reads it (it belongs to another program that
  /// shares the file).
  void skip(const std::string& key);

  /// Records an error (e.g. from a module's validation); the first one wins. A success is ignored.
  void fail(const Status& error);

  /// A validation message of this module ("thickness = 0: must be > 0 m") with this reader's path
  /// in front ("table/thickness = 0: must be > 0 m"). Validation messages of this project always
  /// start with the field name. A success is returned unchanged.
  Status named(const Status& status) const;

  /// No error so far. Unknown keys are only looked for by finish().
  bool ok() const;

  /// The first error; else, if any key of the map was neither read, sectioned nor skipped, an
  /// error naming the first such key (in key order) with its full path and the known keys of that
  /// level: "time_stepp is not a known parameter (known here: fall_off_depth, gravity, ...)"; else
  /// success. A reader whose `values` is not a map: "<path> is ..., expected a map" (path without
  /// the trailing slash; at the root: "the parameters are ..., expected a map").
  Status finish() const;

 private:
  /// The value of `key` if present and no error happened yet; marks `key` known either way.
  const ParameterValue* lookUp(const std::string& key);
  /// Records "<path><name> is <what was found>, expected <expected>".
  void wrongType(const std::string& name, const ParameterValue& found, const std::string& expected);
  /// Reads a list of numbers of any length (`size` < 0) or of exactly `size`.
  bool readNumbers(const std::string& key, int size, std::vector<double>* numbers);

  const ParameterValue* values_;
  std::string path_;
  std::set<std::string> known_;
  Status error_;
};

/// The body every module's reader shares: reads its keys into a copy of
/// `*options` with `read_keys(copy)`; when the module `owns_level` (a section
/// of its own), refuses a key it does not know; validates the copy with the
/// module's validate(), naming the failing key by its path. `*options`
/// changes only on success. A module whose keys share a level with others
/// (the world's at the top) leaves the unknown keys to the caller.
template <typename Options, typename ReadKeys>
Status readAndValidate(OptionsReader& reader, bool owns_level, Options* options,
                       ReadKeys&& read_keys) {
  Options copy = *options;
  read_keys(copy);
  if (owns_level || !reader.ok()) {
    if (Status read = reader.finish(); !read) return read;
  }
  if (Status valid = validate(copy); !valid) return reader.named(valid);
  *options = std::move(copy);
  return Status::success();
}

}  // namespace brick_stack_sim
