// run_view's style sheet: a dark scene, the legend panel on the left and the step panel on the right,
// each a translucent box over the canvas; the verdicts' colours (sx-v1 recovered, sx-v2 untrusted,
// sx-v3 not converged) match the markers the viewer draws.
#include "run_view_script.hpp"

namespace sextant::detail {

const char* run_view_style() {
  return R"(html,body{margin:0;height:100%;overflow:hidden;background:#0f1218;color:#e6e8ec;font-family:DejaVu Sans,Arial,sans-serif}
#sx-canvas{position:fixed;left:0;top:0;width:100vw;height:100vh;display:block;cursor:crosshair}
.sx-box{position:fixed;top:10px;box-sizing:border-box;max-height:calc(100vh - 20px);overflow:auto;background:rgba(18,22,30,.88);border:1px solid #333b4b;border-radius:6px;padding:8px 12px;font-size:13px}
#sx-panel{left:10px;width:330px}
#sx-side{right:10px;width:370px;display:flex;flex-direction:column}
#sx-panel h1{font-size:16px;margin:0 0 4px}
.sx-caption{margin:0 0 6px;color:#b5bac4}
ul.sx-legend{list-style:none;margin:6px 0;padding:0}
ul.sx-legend li{margin:4px 0}
ul.sx-legend li.sx-absent{opacity:.45}
.sx-swatch{display:inline-block;width:16px;height:12px;border-radius:2px;margin:0 6px 0 4px;vertical-align:-1px}
.sx-height{background:linear-gradient(90deg,#26344f,#5f7ca6,#b8cdea)}
.sx-line{height:4px;vertical-align:3px}
.sx-estimate{background:#ffb020}
.sx-reference{background:#e9edf2}
.sx-dot{display:inline-block;width:11px;height:11px;border-radius:50%;margin:0 8px 0 6px;vertical-align:-1px;border:1px solid #0b0d12}
.sx-v0{background:#7fd67f}.sx-v1{background:#26d9c7}.sx-v2{background:#ff4060}.sx-v3{background:#c77dff}.sx-v4{background:#9aa0ab}
.sx-count{color:#959cab;font-size:12px}
.sx-colour{margin:8px 0}
.sx-bar{position:relative;height:12px;margin:4px 0 14px;border-radius:2px;background:linear-gradient(90deg,#2c7bb6,#abd9e9,#ffffbf,#fdae61,#d7191c)}
.sx-bar span{position:absolute;top:13px;font-size:11px;color:#b5bac4;white-space:nowrap}
.sx-bar span:nth-child(1){left:0}.sx-bar span:nth-child(2){left:50%;transform:translateX(-50%)}.sx-bar span:nth-child(3){right:0}
.sx-tools,.sx-nav{display:flex;flex-wrap:wrap;align-items:center;gap:6px;margin:6px 0}
.sx-tools input[type=range]{width:80px;vertical-align:middle}
button,select,input[type=number]{background:#232a38;color:#e6e8ec;border:1px solid #4a5366;border-radius:4px;padding:3px 8px;font:inherit;cursor:pointer}
input[type=number]{width:80px;cursor:text}
button.sx-on{background:#3b6fd8;border-color:#3b6fd8;color:#fff}
.sx-help{color:#959cab;font-size:11px;margin:6px 0 0}
.sx-status{margin:6px 0 0}
.sx-error{color:#ff8a80;font-weight:bold}
.sx-hint{color:#959cab;margin:4px 0}
#sx-step h2{font-size:15px;margin:2px 0 6px}
#sx-step table{border-collapse:collapse;width:100%}
#sx-step th{text-align:left;color:#959cab;font-weight:normal;padding:2px 8px 2px 0;vertical-align:top;white-space:nowrap}
#sx-step td{padding:2px 0;overflow-wrap:anywhere}
.sx-chip{display:inline-block;padding:0 6px;border-radius:3px;color:#0b0d12;font-weight:bold}
#sx-list{overflow:auto;min-height:80px;flex:1 1 auto;border-top:1px solid #333b4b;margin-top:4px}
#sx-list table{border-collapse:collapse;width:100%;font-size:12px}
#sx-list th{position:sticky;top:0;background:#1b212c;text-align:left;padding:3px 4px;color:#b5bac4;font-weight:normal}
#sx-list td{padding:2px 4px;border-bottom:1px solid #252c39;white-space:nowrap}
#sx-list tr[data-step]{cursor:pointer}
#sx-list tr[data-step]:hover{background:#263047}
#sx-list tr.sx-selected{background:#34456b}
#sx-list td.sx-why{white-space:normal;color:#b5bac4}
)";
}

}  // namespace sextant::detail
