#pragma once

#include <cstddef>
#include <string>

#include "brick_stack_sim/core/options/parameter_value.h"
#include "brick_stack_sim/core/status.h"

namespace brick_stack_sim {

/// Parses yaml text into a parameter tree, so that the batch runner reads the same tree the node
/// gets from `rosparam load` of the same file.
///
/// Scalars are typed as rosparam (YAML 1.1) types them: true/false/yes/no/on/off in any case ->
/// bool; an integer literal (optional sign, decimal digits) -> int (out of long long range ->
/// double); other numbers including 1e-3, .5, .inf, -.inf, .nan -> double; a quoted scalar ('...'
/// or "...") is always a string; anything else -> string. The standard tags !!str, !!int, !!float
/// and !!bool are honoured, any other tag on a scalar is an error. A null (`key:` with nothing, or
/// `~`) is an error naming its path ("scene has no value"). So are a key given twice, a key that
/// is not a plain name, a key containing '/', nesting deeper than 100 levels, more than one
/// document and a number out of the range of a double. `source` names the text in messages (a
/// file name); a parse error names it and the line. The top of the document must be a map (an
/// empty document gives an empty map). `*value` is set only on success.
Status parseYamlParameters(const std::string& text, const std::string& source,
                           ParameterValue* value);

/// Reads and parses a file: only a regular file (not a directory, FIFO or device), at most
/// `max_bytes` (default 16 MiB). Messages name the path: "cannot read config '/x.yaml': no such
/// file", "config '/dev/zero' is not a regular file", "config 'big.yaml' is 20000000 bytes, more
/// than the limit of 16777216". The size is checked before reading, and at most max_bytes + 1
/// bytes are read, so a file growing meanwhile cannot exhaust memory. `*value` is set only on
/// success.
Status loadYamlParameters(const std::string& path, ParameterValue* value,
                          std::size_t max_bytes = 16u << 20);

}  // namespace brick_stack_sim
