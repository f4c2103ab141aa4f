// The visual report (`tmcert verify SCENE --report out.html`): one
// self-contained HTML page showing the bodies, their motion on a time
// slider, each check's partition of its interval on a timeline (certified
// safe, undecided, and after a witness not searched), and the witness point
// and features.  three.js and the page's
// own script are embedded (src/html/assets.h); the page fetches nothing.
//
// Everything drawn is for people: coordinates and poses are rounded to
// float for display; the timeline's interval ends are the result's exact
// rationals, as `--json` prints them (data-t0 / data-t1 attributes).
#pragma once

#include "src/verify/verify.h"

#include <string>

namespace tmcert {

// The report page of `result`, the verification of `scene`.
std::string report_html(const Scene& scene, const SceneResult& result);

}  // namespace tmcert
