// src/certificate/checker: the Checker that reads, judges and proves each
// check of a certificate document.  On its own (without check_certificate's
// scope test) it accepts the hand-built certificates with the same
// statements, and names the failing claim with the source it was given.
#include "src/certificate/checker.h"
#include "tests/certificate/check_support.h"

#include <boost/test/unit_test.hpp>

using namespace check_test;
using tmcert::certificate::check_internal::Checker;

BOOST_AUTO_TEST_SUITE(certificate_checker)

BOOST_AUTO_TEST_CASE(same_statements_as_check_certificate) {
  for (const auto& [scene, certificate] : kValid) {
    const Case c = load(scene, certificate);
    const cert::CheckOutcome direct = Checker(c.scene, "cert.json").run(c.certificate);
    const cert::CheckOutcome via = check(c);
    BOOST_TEST(direct.ok, certificate << ": " << direct.message);
    BOOST_TEST(direct.proven == via.proven, certificate);
  }
}

BOOST_AUTO_TEST_CASE(rejection_names_the_source_and_the_claim) {
  Case c = load("solid-inside", "solid-inside-safe");
  const cert::CheckOutcome out = Checker(c.scene, "mine.json").run(c.certificate);
  BOOST_TEST(!out.ok);
  BOOST_TEST(out.message.rfind("mine.json: ", 0) == 0u, out.message);
  BOOST_TEST(out.message.find("start[0] (solid \"box\")") != std::string::npos, out.message);
  BOOST_TEST(out.proven.empty());
}

BOOST_AUTO_TEST_SUITE_END()
