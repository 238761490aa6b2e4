#include "tools/common/vtu_flags.h"

#include <string>

#include <gflags/gflags.h>

#include "ergo/mesh/input_error.h"

DEFINE_string(vtu_format, "binary",
              "encoding of the VTU files written: binary (raw appended arrays, compact) or "
              "ascii (text, about twice the size and ten times the write time)");

namespace ergo {

VtuEncoding VtuEncodingFromFlags() {
  VtuEncoding encoding = VtuEncoding::kBinary;
  if (!ParseVtuEncoding(FLAGS_vtu_format, &encoding)) {
    throw InputError("--vtu_format", "", "'" + FLAGS_vtu_format + "' is not a VTU encoding",
                     "use --vtu_format=binary or --vtu_format=ascii");
  }
  return encoding;
}

}  // namespace ergo
