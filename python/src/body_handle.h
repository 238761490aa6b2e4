// The Python object behind ergo.Body: a layered body shared between the Python object and
// everything that keeps a reference to it (a scenario's design problems).
#pragma once

#include <memory>

#include "ergo/body/layered_body.h"

namespace ergo::python {

struct BodyHandle {
  std::shared_ptr<const LayeredBody> body;
};

}  // namespace ergo::python
