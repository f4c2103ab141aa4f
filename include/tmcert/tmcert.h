// tmcert: certified collision checks of moving polyhedra, the public C++ API.
//
//   #include <tmcert/tmcert.h>
//
//   tmcert::SceneBuilder b;                       // or tmcert::Scene::from_file(...)
//   b.add_body("table").triangles(xyz, indices);
//   b.add_body("box").triangles(box_xyz, box_indices)
//       .motion(tmcert::Motion::translation({0, 0, 2}, {0, 0, "-1/2"}));
//   const tmcert::Result r = tmcert::verify(b.build());
//   if (r.verdict() == tmcert::Verdict::Collision) ...
//
// Headers: numbers.h (Number, Rational, Time), motion.h (Motion, Pose, ...),
// scene_builder.h (SceneBuilder), scene.h (Scene), verify.h (verify,
// VerifyOptions), result.h (Result, CheckResult, Witness), certificate.h
// (check_certificate), errors.h (InputError, ResourceLimit, Cancelled),
// batch.h (batch, batch_merge), environment.h (Environment: many motions
// of one body against obstacles prepared once, from several threads).  They use only the C++20 standard library;
// link the target tmcert::tmcert (shared) or tmcert::tmcert_static from
// find_package(tmcert).  ompl.h, the certified OMPL motion validator, is
// not included here: it needs OMPL; link tmcert::ompl from
// find_package(tmcert COMPONENTS ompl).
//
// Namespaces.  Every public type and function is declared in
// `tmcert::api`, and every public header makes it visible as `tmcert::X`
// with `namespace tmcert { using namespace api; }`: users write
// `tmcert::SceneBuilder`, `tmcert::Scene`, `tmcert::verify(...)`.  The
// library's internals (not installed) live in `tmcert` itself and use some
// of the same names (tmcert::Scene is the internal exact model there);
// declaring the public types in their own namespace keeps one definition
// per qualified name.  Only the library's own sources (src/api/) see both.
#pragma once

#include "tmcert/batch.h"
#include "tmcert/certificate.h"
#include "tmcert/environment.h"
#include "tmcert/errors.h"
#include "tmcert/export.h"
#include "tmcert/motion.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"
#include "tmcert/scene_builder.h"
#include "tmcert/verify.h"

namespace tmcert {
using namespace api;
}
