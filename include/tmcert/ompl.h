// tmcert's certified motion validator for OMPL planners, on the public API.
//
//   #include <tmcert/ompl.h>
//
//   const tmcert::Scene scene = tmcert::Scene::from_file("cell.json");   // or SceneBuilder
//   ompl::geometric::SimpleSetup setup(std::make_shared<ompl::base::SE3StateSpace>());
//   auto validator = tmcert::use_certified_se3(setup.getSpaceInformation(), scene, "gripper");
//   ... plan; validator->checkMotion(s1, s2) is true only for a certified-safe edge
//   const tmcert::EdgeResult e = tmcert::certify_edge(*validator, s1, s2);
//
// An edge (OMPL's straight segment between two states) is accepted only
// when it is proven free of contact; undecided edges (within epsilon of
// contact, out of budget) and edges without a certified meaning count as
// invalid.  README.md "Plugging tmcert into an OMPL planner" and
// proofs/ompl-validator.md say exactly what is certified.
//
// The scene gives the geometry: the robot (one body, or a URDF robot of the
// scene's "robots") and the obstacles, every other body of the scene, which
// must be fixed (no motion over an interval; a one-pose motion places the
// body).  The motions of the robot in the scene are ignored (the planner
// gives them), and so are the scene's checks.  Not supported (InputError):
// tolerances, clearances, and solid obstacles next to other obstacles.
//
// Epsilon (the termination tolerance of each edge): VerifyOptions::epsilon,
// else the scene's, else 1/1000 of the diagonal of the box of everything
// the scene's bodies sweep along their motions as written, refined: an
// edge's undecided parts are searched again at epsilon/10, ... down to
// epsilon/10^6, within time_limit (else 30 s, first search included) per check (`tmcert batch`
// makes the same choice; "auto" refines even when the scene gives an
// epsilon, a given number does not).  Also used: kernel (filtered or exact; the fast
// kernel is not certified: InputError), max_depth (else the scene's),
// time_limit (per check of an edge: one moving body against the obstacles
// or another link), all_pairs; threads and certificate are not (an edge is
// one search; no certificates of edges).
//
// The adapter is the CMake target tmcert::ompl (it needs OMPL, Debian's
// libompl-dev): find_package(tmcert REQUIRED COMPONENTS ompl) for an
// installed tmcert, or the same target after add_subdirectory.
#pragma once

#include "tmcert/errors.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"
#include "tmcert/verify.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorBounds.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::api {

// Installs tmcert's certified state validity checker and motion validator
// in `si`, whose state space must be an ompl::base::SE3StateSpace, for the
// rigid body `robot_body` of `scene` (its geometry in its own frame; an SE(3)
// state is its pose, read exactly as the doubles it holds) among every
// other body of the scene, and returns the motion validator.  Call before
// si->setup().  Throws InputError (naming the field) for another state
// space, an unknown body, an obstacle that moves, bad options.
std::shared_ptr<ompl::base::MotionValidator> use_certified_se3(const ompl::base::SpaceInformationPtr& si,
                                                               const Scene& scene, const std::string& robot_body,
                                                               const VerifyOptions& options = {});

// The same for the URDF robot `robot_name` of the scene's "robots" (at its
// base pose) planned in joint space: si's state space must be an
// ompl::base::RealVectorStateSpace whose dimension k is the position of
// joint `joints[k]` (every moving joint, each once); an edge is the linear
// joint motion between two states, and every link with collision geometry
// is certified against the obstacles (every body of the scene that is not
// one of the robot's links) and, with `self_collision`, against the other
// links that are neither its parent nor its child nor listed in
// `allowed_pairs` (link names).  States outside a joint's <limit> are
// invalid.
std::shared_ptr<ompl::base::MotionValidator> use_certified_arm(
    const ompl::base::SpaceInformationPtr& si, const Scene& scene, const std::string& robot_name,
    const std::vector<std::string>& joints, bool self_collision = true,
    const std::vector<std::pair<std::string, std::string>>& allowed_pairs = {}, const VerifyOptions& options = {});

// The <limit>s of the joints `joints` of robot `robot_name` of the scene as
// bounds of a RealVectorStateSpace (dimension k: joint `joints[k]`), each
// rounded inward to a double so that every state within the bounds is
// within the exact limits.  Throws InputError for an unknown robot or
// joint, or a joint without both limits (continuous, fixed).
ompl::base::RealVectorBounds joint_bounds(const Scene& scene, const std::string& robot_name,
                                          const std::vector<std::string>& joints);

// The certified outcome of one edge.
struct EdgeResult {
  // Safe: proven free (checkMotion's true); collision: proven contact;
  // undecided: neither, or the edge has no certified meaning (`problem`).
  Verdict verdict = Verdict::Undecided;
  // The edge parameter runs from 0 (s1) to 1 (s2).  Brackets the earliest
  // possible contact: the part of the edge before its lower end is
  // certified free.  Absent when the edge is safe, or with a `problem`.
  std::optional<std::array<Rational, 2>> first_contact;
  // Of the check that decided a collision: the bodies (names; a robot's
  // link as "<robot>/<link>", the obstacles together as "obstacles"; empty
  // for a state's exact static test, whose witness's features name them)
  // and the witness (its time t on the edge's parameter).
  std::array<std::string, 2> bodies;
  std::optional<Witness> witness;
  std::string problem;  // why the edge could not be certified at all (non-finite state, no shorter arc, ...)
};

// Certifies the edge from s1 to s2 (with s1 == s2 as pointers: the state)
// with a validator returned by use_certified_se3 or use_certified_arm.
// Throws InputError for any other validator.
EdgeResult certify_edge(const ompl::base::MotionValidator& validator, const ompl::base::State* s1,
                        const ompl::base::State* s2);

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
