// --vtu_format: how the tools that write VTU files (ergo_body's body.vtu, ergo_simulate's and
// ergo_optimize's body and support views) store them — binary (the default: raw appended
// arrays, lossless, about half the size and a tenth of the write time) or ascii (text, for
// reading by eye or by tools without a binary VTU reader). A tool gets the flag by calling
// VtuEncodingFromFlags (this file is linked only into the tools that do: ergo_compare and
// ergo_bump write no VTU).
#pragma once

#include "ergo/mesh/vtu_writer.h"

namespace ergo {

// The encoding --vtu_format names; InputError naming --vtu_format for any other word. Call it
// with the tool's other flag checks, before any work.
VtuEncoding VtuEncodingFromFlags();

}  // namespace ergo
