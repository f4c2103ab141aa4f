// Fuzz target: differential test of the kernels (tests/fuzz/README.md).
// The input bytes spell two triangles and a ball placement (small
// integers, dyadic fractions, values 1 ulp apart and raw doubles, so that
// degenerate and near-degenerate inputs are frequent); the target runs the
// same predicates with the filtered kernel (intervals, exact fallback) and
// with exact rationals alone, and requires:
//  - contact_sign: filtered == exact for every feature pair and kind;
//  - the static test's interval filter: certainly_disjoint (intervals) is
//    never true where the exact common_point finds a common point;
//  - collinear (filtered) == the exact cross product test.
#include "kernels/contact.h"
#include "kernels/filtered.h"
#include "kernels/static_intersection.h"
#include "src/verify/prepared.h"
#include "tests/fuzz/fuzz.h"
#include "tests/support/random_geometry.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace {

class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t byte() { return i_ < n_ ? d_[i_++] : 0; }
  double value() {
    const std::uint8_t mode = byte();
    const int k = static_cast<std::int8_t>(byte());
    switch (mode % 8) {
      case 0: case 1: case 2: return k % 9;                          // small integers, many equal
      case 3: case 4: return std::ldexp(k, -static_cast<int>(byte() % 64));  // dyadic
      case 5: return std::nextafter(static_cast<double>(k % 3), mode & 8 ? 1e9 : -1e9);  // 1 ulp off
      case 6: {  // a raw double; only finite ones are scene numbers
        double x;
        std::uint8_t raw[8];
        for (auto& b : raw) b = byte();
        std::memcpy(&x, raw, 8);
        return std::isfinite(x) ? x : 0.0;
      }
      default: return std::ldexp(k, static_cast<int>(byte() % 128) - 64);  // wide scales
    }
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

std::string describe(const std::array<tmcert::Vec3E, 3>& a, const std::array<tmcert::Vec3E, 3>& b) {
  std::ostringstream out;
  for (const auto* t : {&a, &b}) {
    out << "[";
    for (const auto& p : *t) out << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    out << "]";
  }
  return out.str();
}

tmcert::SimplexI to_interval(const tmcert::Simplex& s) {
  tmcert::SimplexI out;
  out.count = s.count;
  for (int i = 0; i < s.count; ++i)
    for (int c = 0; c < 3; ++c) out.p[i][c] = CGAL::to_interval(s.p[i][c]);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tmcert;
  if (size < 8 || size > 4096) return 0;
  Bytes in(data, size);
  std::array<Vec3E, 3> tm, tf;
  for (auto* t : {&tm, &tf})
    for (auto& p : *t) p = {Exact(in.value()), Exact(in.value()), Exact(in.value())};

  // The static test: exact common point versus the interval filter, for
  // every sub-simplex count (point, segment, triangle) of each triangle.
  for (int ca = 1; ca <= 3; ++ca)
    for (int cb = 1; cb <= 3; ++cb) {
      Simplex a{ca, tm}, b{cb, tf};
      const std::optional<Vec3E> common = common_point(a, b);
      bool disjoint;
      {
        RoundingGuard guard;
        disjoint = certainly_disjoint(to_interval(a), to_interval(b));
      }
      if (disjoint && common)
        fuzz::fail("certainly_disjoint on simplices with a common point: " + describe(tm, tf));
    }
  for (const auto* t : {&tm, &tf})
    if (collinear((*t)[0], (*t)[1], (*t)[2]) != testing::collinear(*t))
      fuzz::fail("collinear (filtered) differs from the exact test: " + describe(tm, tf));

  // The contact predicate: filtered versus exact.
  if (testing::collinear(tm) || testing::collinear(tf)) return 0;
  Body bm = testing::triangle_body("m", tm), bf = testing::triangle_body("f", tf);
  bm.motion = Motion{0, 1, {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}}, {1, 1}};
  const PreparedBody pm(bm), pf(bf);
  Placement<Interval> pi;
  Placement<Exact> pe;
  for (int e = 0; e < 12; ++e) {
    const double g = in.value();
    pi.g1[e] = Interval(g);
    pe.g1[e] = Exact(g);
  }
  const double r2 = std::abs(in.value());
  pi.r2 = Interval(r2);
  pe.r2 = Exact(r2);
  for (ContactKind kind : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
    const FeatureTable& X = kind == ContactKind::VertexFace ? pm.vertices : kind == ContactKind::EdgeEdge ? pm.edges : pm.faces;
    const FeatureTable& Y = kind == ContactKind::VertexFace ? pf.faces : kind == ContactKind::EdgeEdge ? pf.edges : pf.vertices;
    const auto& Xe = kind == ContactKind::VertexFace ? pm.exact().vertices : kind == ContactKind::EdgeEdge ? pm.exact().edges : pm.exact().faces;
    const auto& Ye = kind == ContactKind::VertexFace ? pf.exact().faces : kind == ContactKind::EdgeEdge ? pf.exact().edges : pf.exact().vertices;
    for (std::size_t i = 0; i < X.size(); ++i)
      for (std::size_t j = 0; j < Y.size(); ++j) {
        const CGAL::Sign exact = contact_sign<Exact>(kind, Xe[i], Ye[j], pe);
        FilterCounters counters;
        const CGAL::Sign filt = filtered([&] { return contact_sign<Interval>(kind, X.interval[i], Y.interval[j], pi); },
                                         [&] { return contact_sign<Exact>(kind, Xe[i], Ye[j], pe); }, counters);
        if (filt != exact)
          fuzz::fail("contact_sign: filtered " + std::to_string(int(filt)) + ", exact " + std::to_string(int(exact)) +
                     " (kind " + std::to_string(int(kind)) + ", features " + std::to_string(i) + ", " +
                     std::to_string(j) + "): " + describe(tm, tf));
      }
  }
  return 0;
}
