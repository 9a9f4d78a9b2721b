#pragma once
// Private helper of the eval module: the browser side of run_view's pages: the style sheet, the step
// panel (the selected step's details, the list of marked steps, previous / next / go to) and the viewer
// (the map, the trajectories and the markers drawn with three.js; the orbit and top cameras; picking a
// step with the mouse). Both scripts go into one <script> element after the page's JSON, the panel first.
namespace sextant::detail {

/// CSS for the page (the canvas filling the window, the legend panel on the left, the step panel on the
/// right).
const char* run_view_style();
/// Defines sxRunPanel(data, hooks), which the viewer calls.
const char* run_view_panel_script();
/// The viewer, run after three.js, its line scripts and the <script id="sx-data"> JSON block.
const char* run_view_script();

}  // namespace sextant::detail
