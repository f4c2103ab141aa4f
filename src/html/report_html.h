// The visual report (`tmcert verify SCENE --report out.html`): one
// self-contained HTML page showing the bodies, their motion on a time
// slider, each check's certified-safe, undecided and colliding intervals on
// a timeline, and the witness point and features.  three.js and the page's
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

// Throws InputError naming `option` when `path` cannot be opened for
// writing (a missing folder, a folder, a read-only file).  Leaves an
// existing file as it is, and creates none.  For checking an output path
// before a long verification.
void require_writable(const std::string& path, const std::string& option);

// Writes `text` to `path`; throws InputError naming `option` when it cannot.
void write_text_file(const std::string& path, const std::string& text, const std::string& option);

}  // namespace tmcert
