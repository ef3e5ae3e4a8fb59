#pragma once
/// \file
/// The files that `newtop view` puts into its page, compiled into the program (viewer/embed.cmake)
/// so that the page it writes works offline, opened from disk, with nothing installed.

#include <string_view>

namespace newtop::viewer::assets {

std::string_view page_html();          ///< viewer/view.html, with @NAME@ placeholders
std::string_view three_js();           ///< three.js (MIT licence), Debian's libjs-three
std::string_view orbit_controls_js();  ///< three.js's OrbitControls (same package)
std::string_view drift_js();           ///< viewer/drift.js
std::string_view viewer_js();          ///< viewer/viewer.js
std::string_view three_js_revision();  ///< the three.js release embedded (e.g. "r111")

}  // namespace newtop::viewer::assets
