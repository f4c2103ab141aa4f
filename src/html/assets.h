// The files the visual report embeds, compiled into the library by
// cmake/EmbedReportAssets.cmake (no file is looked up at run time).
#pragma once

#include <string_view>

namespace tmcert::html {

extern const std::string_view kThreeCore;      // third_party/three/three.core.min.js
extern const std::string_view kThreeModule;    // three.module.min.js, importing "three/core"
extern const std::string_view kOrbitControls;  // three/examples/jsm/controls/OrbitControls.js
extern const std::string_view kThreeVersion;   // third_party/three/VERSION
extern const std::string_view kReportApp;      // src/html/report_app.js
extern const std::string_view kReportStyle;    // src/html/report.css

}  // namespace tmcert::html
