// Re-checking a certificate (tmcert-certificate/1, docs/certificate-format.md)
// in exact arithmetic, as `tmcert check` does.  Certificates are written by
// Result::certificate() and Result::write_certificate().
#pragma once

#include "tmcert/export.h"
#include "tmcert/scene.h"

#include <string>
#include <vector>

namespace tmcert::api {

struct CertificateCheck {
  bool ok = false;              // every claim of the certificate is proven
  std::string message;          // when !ok: one line naming the failing claim
  std::vector<std::string> proven;  // per check, what was proven (when ok)
};

// Checks the certificate file `path` against `scene`.  A certificate that
// is malformed is an InputError; one whose claims fail is !ok.
TMCERT_API CertificateCheck check_certificate(const Scene& scene, const std::string& path);
// The same for a certificate document in memory (`source` names it).
TMCERT_API CertificateCheck check_certificate_text(const Scene& scene, const std::string& text,
                                                   const std::string& source = "<certificate>");

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
