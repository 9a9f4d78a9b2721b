// The browser side of cloud_view's pages: style sheet and viewer script (ES5, no modules, no
// network). The script decodes each cloud's float32 coordinates (base64, little-endian), draws
// them as THREE.Points placed by the current state's pose, and moves an orbit camera (z up) with
// the mouse: left drag rotates, right/middle or shift drag pans, the wheel zooms, double-click or R
// resets, keys 1–9 pick a state; "#state=N" in the URL opens state N. It draws on demand only. For checks
// without pixels it records on <body> how many points it decoded per cloud (data-sx-decoded) and whether
// WebGL drew (data-sx-webgl = "ok" or the reason it did not).
#include "cloud_view_script.hpp"

namespace sextant::detail {

const char* cloud_view_style() {
  return R"(html,body{margin:0;height:100%;overflow:hidden;background:#10131a;color:#e8e8e8;font-family:DejaVu Sans,Arial,sans-serif}
#sx-canvas{position:fixed;left:0;top:0;width:100vw;height:100vh;display:block;cursor:grab}
#sx-canvas:active{cursor:grabbing}
#sx-panel{position:fixed;top:10px;left:10px;max-width:380px;max-height:calc(100vh - 20px);overflow:auto;box-sizing:border-box;background:rgba(16,19,26,.85);border:1px solid #343b4a;border-radius:6px;padding:8px 12px;font-size:13px}
#sx-panel h1{font-size:16px;margin:0 0 4px}
.sx-caption{margin:0 0 6px;color:#b8bcc6}
.sx-states{display:flex;flex-wrap:wrap;gap:4px;margin:6px 0}
.sx-states button,#sx-reset{background:#232a38;color:#e8e8e8;border:1px solid #4a5366;border-radius:4px;padding:3px 8px;font:inherit;cursor:pointer}
.sx-states button.sx-on{background:#3b6fd8;border-color:#3b6fd8;color:#fff}
ul.sx-legend{list-style:none;margin:6px 0;padding:0}
ul.sx-legend li{margin:3px 0}
ul.sx-legend li.sx-absent{opacity:.4}
.sx-swatch{display:inline-block;width:12px;height:12px;border-radius:2px;margin:0 6px 0 4px;vertical-align:-1px}
.sx-count{color:#9aa0ab;font-size:12px}
.sx-tools{display:flex;align-items:center;gap:10px;margin:6px 0}
.sx-tools input[type=range]{width:90px;vertical-align:middle}
.sx-help{color:#9aa0ab;font-size:11px;margin:6px 0 0}
.sx-status{margin:6px 0 0}
.sx-error{color:#ff8a80;font-weight:bold}
)";
}

const char* cloud_view_script() {
  return R"JS((function () {
  'use strict';
  var body = document.body;
  var status = document.getElementById('sx-status');
  function say(text, error) {
    status.textContent = text;
    status.className = error ? 'sx-status sx-error' : 'sx-status';
  }
  var data = JSON.parse(document.getElementById('sx-data').textContent);

  function decode(text) {
    var bin = atob(text), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    var view = new DataView(bytes.buffer), out = new Float32Array(bytes.length / 4);
    for (var k = 0; k < out.length; ++k) out[k] = view.getFloat32(4 * k, true);
    return out;
  }
  var positions = data.clouds.map(function (c) { return decode(c.points); });
  body.setAttribute('data-sx-decoded', positions.map(function (p) { return p.length / 3; }).join(','));

  if (typeof THREE === 'undefined') {
    say('three.js did not load (' + data.three + '). It comes from the Debian package libjs-three.', true);
    body.setAttribute('data-sx-webgl', 'three.js missing');
    return;
  }
  var canvas = document.getElementById('sx-canvas'), renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas: canvas, preserveDrawingBuffer: true});
  } catch (e) {
    say('WebGL is not available in this browser: ' + e.message, true);
    body.setAttribute('data-sx-webgl', 'no WebGL');
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0x10131a, 1);
  var scene = new THREE.Scene();
  var camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);

  var slider = document.getElementById('sx-size');
  var size = parseFloat(slider.value) || 2, state = 0, shown = data.clouds.map(function () { return true; });
  var objects = data.clouds.map(function (c, i) {
    var geometry = new THREE.BufferGeometry(), attribute = new THREE.BufferAttribute(positions[i], 3);
    if (geometry.setAttribute) geometry.setAttribute('position', attribute);
    else geometry.addAttribute('position', attribute);
    geometry.computeBoundingBox();
    var material = new THREE.PointsMaterial({color: new THREE.Color(c.color), size: size, sizeAttenuation: false});
    var points = new THREE.Points(geometry, material);
    points.matrixAutoUpdate = false;
    scene.add(points);
    return points;
  });

  // Framing from the page (robust bounds over every cloud in every state: it stays when the state
  // changes); the far plane covers every point.
  var centre = new THREE.Vector3().fromArray(data.centre), radius = data.radius, extent = radius;
  data.clouds.forEach(function (c, i) {
    if (positions[i].length === 0) return;
    c.poses.forEach(function (pose) {
      if (!pose) return;
      var box = objects[i].geometry.boundingBox.clone().applyMatrix4(new THREE.Matrix4().fromArray(pose));
      extent = Math.max(extent, box.distanceToPoint(centre) + box.getSize(new THREE.Vector3()).length());
    });
  });
  var halfFov = camera.fov * Math.PI / 360;
  var orbit = {};

  var pending = false, width = 0, height = 0;
  function draw() {
    pending = false;
    var w = window.innerWidth, h = window.innerHeight;
    if (w !== width || h !== height) {
      width = w, height = h;
      renderer.setSize(w, h, false);
      camera.aspect = w / Math.max(h, 1);
    }
    var ce = Math.cos(orbit.elevation), t = orbit.target;
    camera.position.set(t.x + orbit.distance * ce * Math.cos(orbit.azimuth),
                        t.y + orbit.distance * ce * Math.sin(orbit.azimuth),
                        t.z + orbit.distance * Math.sin(orbit.elevation));
    camera.lookAt(t);
    camera.far = camera.position.distanceTo(centre) + 2 * extent;
    camera.near = Math.max(camera.far * 1e-4, orbit.distance * 1e-3);
    camera.updateProjectionMatrix();
    camera.updateMatrixWorld();
    renderer.render(scene, camera);
  }
  function redraw() {
    if (!pending) {
      pending = true;
      requestAnimationFrame(draw);
    }
  }
  function reset() {
    orbit.target = centre.clone();
    orbit.azimuth = -Math.PI / 2 - 0.5;
    orbit.elevation = 0.8;
    orbit.distance = 1.05 * radius / Math.sin(halfFov);
    redraw();
  }

  var items = document.querySelectorAll('ul.sx-legend li'), buttons = document.querySelectorAll('.sx-states button');
  function apply() {
    objects.forEach(function (o, i) {
      var pose = data.clouds[i].poses[state];
      o.visible = !!pose && shown[i];
      if (pose) {
        o.matrix.fromArray(pose);
        o.matrixWorldNeedsUpdate = true;
      }
      o.material.size = size;
      if (items[i]) items[i].className = pose ? '' : 'sx-absent';
    });
    for (var b = 0; b < buttons.length; ++b) buttons[b].className = b === state ? 'sx-on' : '';
    redraw();
  }
  function choose(s) {
    if (s >= 0 && s < data.states) {
      state = s;
      apply();
    }
  }

  Array.prototype.forEach.call(document.querySelectorAll('input[data-cloud]'), function (input) {
    input.addEventListener('change', function () {
      shown[parseInt(input.getAttribute('data-cloud'), 10)] = input.checked;
      apply();
    });
  });
  Array.prototype.forEach.call(buttons, function (button) {
    button.addEventListener('click', function () { choose(parseInt(button.getAttribute('data-state'), 10)); });
  });
  slider.addEventListener('input', function () {
    size = parseFloat(slider.value);
    apply();
  });
  document.getElementById('sx-reset').addEventListener('click', reset);

  var drag = null;
  canvas.addEventListener('contextmenu', function (e) { e.preventDefault(); });
  canvas.addEventListener('pointerdown', function (e) {
    drag = {x: e.clientX, y: e.clientY, pan: e.button !== 0 || e.shiftKey || e.ctrlKey};
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', function (e) {
    if (!drag) return;
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX, drag.y = e.clientY;
    if (drag.pan) {
      var scale = 2 * orbit.distance * Math.tan(halfFov) / Math.max(canvas.clientHeight, 1);
      var right = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
      var up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
      orbit.target.addScaledVector(right, -dx * scale).addScaledVector(up, dy * scale);
    } else {
      orbit.azimuth -= dx * 0.006;
      orbit.elevation = Math.max(-1.55, Math.min(1.55, orbit.elevation + dy * 0.006));
    }
    redraw();
  });
  function release() { drag = null; }
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', function (e) {
    e.preventDefault();
    var unit = e.deltaMode === 1 ? 40 : e.deltaMode === 2 ? 800 : 1;
    orbit.distance = Math.max(radius * 1e-3, Math.min(extent * 20, orbit.distance * Math.exp(e.deltaY * unit * 0.0015)));
    redraw();
  }, {passive: false});
  canvas.addEventListener('dblclick', reset);
  window.addEventListener('keydown', function (e) {
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    if (e.key === 'r' || e.key === 'R') reset();
    var n = parseInt(e.key, 10);
    if (n >= 1 && n <= 9) choose(n - 1);
  });
  window.addEventListener('resize', redraw);

  // "page.html#state=2" opens the second state.
  var asked = /state=(\d+)/.exec(window.location.hash);
  if (asked) state = Math.min(Math.max(parseInt(asked[1], 10) - 1, 0), data.states - 1);
  apply();
  reset();
  draw();
  say('');
  body.setAttribute('data-sx-webgl', 'ok');
})();
)JS";
}

}  // namespace sextant::detail
