#pragma once
// Private helper of the eval module: the browser side of cloud_view's pages (the style sheet and
// the viewer script that reads the page's JSON, draws the clouds with three.js and handles the
// legend toggles, the state buttons and the mouse).
namespace sextant::detail {

/// CSS for the page (canvas filling the window, the panel over it).
const char* cloud_view_style();
/// The viewer, run after three.js and the <script id="sx-data"> JSON block.
const char* cloud_view_script();

}  // namespace sextant::detail
