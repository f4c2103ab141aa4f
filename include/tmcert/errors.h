// The exceptions of the public API.
#pragma once

#include "tmcert/export.h"

#include <stdexcept>

namespace tmcert::api {

// Bad input: a scene (built in code, or read from a file or text), an
// option or a certificate that is malformed or out of its limits.  The
// message is one line naming the file (or "SceneBuilder"), the field as a
// JSON path of the tmcert-scene/1 document (e.g.
// "SceneBuilder: bodies[1].motion.weights[2]: weight must be positive") and
// what is wrong; the command line turns it into exit code 3.
class TMCERT_API InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A resource limit that leaves no honest answer (the command line's exit
// code 4).  A limit that still allows an honest "undecided" (time, nodes,
// depth) is reported as an undecided interval instead, never as this.
class TMCERT_API ResourceLimit : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The run was cancelled (VerifyOptions::progress returned false, or a
// batch's progress callback did): there is no result.
class TMCERT_API Cancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
