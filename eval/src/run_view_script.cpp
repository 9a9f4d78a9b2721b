// The viewer of run_view's pages (ES5, no modules, no network). It decodes the map and the poses
// (float32, base64, little-endian, relative to the scene's centre), shades the map by height, draws the
// trajectories as fat lines (libjs-three's Line2; the estimate plain or coloured by its error) and one
// round marker per marked step, each verdict its own colour, all over the map. The camera orbits
// (z up: drag rotates, right / shift drag pans, the wheel zooms) or looks straight down (top view,
// north up: drag pans). A click picks the step nearest the pointer (marked ones first, within 14 px)
// and the panel shows it; "#step=N" opens step N, "#top" the top view. It draws on demand only. For
// checks without pixels it records on <body> what it decoded (data-sx-decoded: map points, poses,
// steps), the markers per verdict (data-sx-markers: untrusted, not converged, recovered), what the
// first frame painted (data-sx-painted: pixels off the background, of the estimate's colour, of the
// untrusted markers' colour), and data-sx-drawn = "ok" once it is drawn (or the reason it was not).
#include "run_view_script.hpp"

namespace sextant::detail {

const char* run_view_script() {
  return R"JS((function () {
  'use strict';
  var body = document.body, status = document.getElementById('sx-status');
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
  var map = decode(data.map.points), poses = decode(data.estimate.points);
  var reference = data.reference ? decode(data.reference.points) : null, steps = data.steps;
  body.setAttribute('data-sx-decoded', [map.length / 3, poses.length / 3, steps.count].join(','));
  var hooks = {}, panel = sxRunPanel(data, hooks);
  var stepAt = new Int32Array(data.estimate.count);  // the step drawn at each pose, or -1
  for (var p = 0; p < stepAt.length; ++p) stepAt[p] = -1;
  for (var s = 0; s < steps.count; ++s) stepAt[steps.pose[s]] = s;

  function fail(why) {
    say(why, true);
    body.setAttribute('data-sx-drawn', why);
  }
  if (typeof THREE === 'undefined' || !THREE.Line2) return fail('three.js did not load: it comes from the Debian package libjs-three.');
  var canvas = document.getElementById('sx-canvas'), renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (e) {
    return fail('WebGL is not available in this browser: ' + e.message);
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0x0f1218, 1);
  var scene = new THREE.Scene(), vertexColors = THREE.VertexColors !== undefined ? THREE.VertexColors : true;
  var radius = data.radius, extent = radius;

  function points(positions, colours, material, order) {
    var g = new THREE.BufferGeometry();
    var set = function (name, a) { if (g.setAttribute) g.setAttribute(name, a); else g.addAttribute(name, a); };
    set('position', new THREE.BufferAttribute(positions, 3));
    if (colours) set('color', new THREE.BufferAttribute(colours, 3));
    g.computeBoundingSphere();
    if (g.boundingSphere && isFinite(g.boundingSphere.radius))
      extent = Math.max(extent, g.boundingSphere.center.length() + g.boundingSphere.radius);
    var o = new THREE.Points(g, material);
    o.renderOrder = order;
    scene.add(o);
    return o;
  }
  // The map, shaded by height between its 2 % and 98 % quantiles (dark low, light high).
  function ramp(stops, t, out, at) {
    t = Math.max(0, Math.min(1, t)) * (stops.length - 1);
    var k = Math.min(stops.length - 2, Math.floor(t)), f = t - k;
    for (var c = 0; c < 3; ++c) out[at + c] = (stops[k][c] + f * (stops[k + 1][c] - stops[k][c])) / 255;
  }
  var layers = {};
  if (map.length) {
    var zs = [];
    for (var z = 2; z < map.length; z += 3 * Math.max(1, Math.floor(map.length / 60000))) zs.push(map[z]);
    zs.sort(function (a, b) { return a - b; });
    var zlo = zs[Math.floor(0.02 * (zs.length - 1))], zhi = zs[Math.floor(0.98 * (zs.length - 1))];
    var shades = new Float32Array(map.length), height = [[38, 52, 79], [95, 124, 166], [184, 205, 234]];
    for (var m = 0; m < map.length; m += 3) ramp(height, (map[m + 2] - zlo) / Math.max(zhi - zlo, 1e-6), shades, m);
    layers.map = points(map, shades, new THREE.PointsMaterial({size: 1.5, vertexColors: vertexColors, sizeAttenuation: false}), 0);
  }
  // The trajectories as fat lines over the map.
  var width = 0, height = 0, lineMaterials = [];
  function fatLine(positions, colours, px, order) {
    var g = new THREE.LineGeometry();
    g.setPositions(positions);
    g.setColors(colours);
    var material = new THREE.LineMaterial({linewidth: px, vertexColors: vertexColors, depthTest: false});
    lineMaterials.push(material);
    var line = new THREE.Line2(g, material);
    line.renderOrder = order;
    scene.add(line);
    return line;
  }
  function plain(n, rgb) {
    var c = new Float32Array(3 * n);
    for (var i = 0; i < c.length; ++i) c[i] = rgb[i % 3];
    return c;
  }
  if (reference && reference.length >= 6) layers.reference = fatLine(reference, plain(reference.length / 3, [0.85, 0.87, 0.9]), 6, 1);
  var line = data.estimate.line, vertices = new Float32Array(3 * line.length);
  for (var v = 0; v < line.length; ++v) for (var c = 0; c < 3; ++c) vertices[3 * v + c] = poses[3 * line[v] + c];
  var errorAt = new Float32Array(data.estimate.count);  // the error of the step drawn at each pose, NaN none
  for (var e = 0; e < errorAt.length; ++e) errorAt[e] = stepAt[e] >= 0 && steps.error_m[stepAt[e]] !== null ? steps.error_m[stepAt[e]] : NaN;
  var errorStops = [[44, 123, 182], [171, 217, 233], [255, 255, 191], [253, 174, 97], [215, 25, 28]];
  function estimateColours(byError) {
    var out = plain(line.length, [1, 0.69, 0.125]);
    if (byError)
      for (var i = 0; i < line.length; ++i) {
        var x = errorAt[line[i]];
        if (isNaN(x)) out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = 0.6;
        else ramp(errorStops, x / data.error_scale, out, 3 * i);
      }
    return out;
  }
  var byError = document.getElementById('sx-by-error');
  if (line.length >= 2) layers.estimate = fatLine(vertices, estimateColours(byError && byError.checked), 3.5, 2);
  if (document.getElementById('sx-scale')) {
    document.getElementById('sx-scale-mid').textContent = (data.error_scale / 2).toPrecision(2) + ' m';
    document.getElementById('sx-scale').textContent = '≥ ' + data.error_scale.toPrecision(2) + ' m';
  }

  // Round markers (a disc with a dark rim), one Points object per verdict; the selection is a ring.
  function sprite(ring) {
    var c = document.createElement('canvas');
    c.width = c.height = 64;
    var g = c.getContext('2d');
    g.beginPath();
    g.arc(32, 32, ring ? 25 : 28, 0, 2 * Math.PI);
    if (ring) {
      g.lineWidth = 7;
      g.strokeStyle = '#ffffff';
      g.stroke();
    } else {
      g.fillStyle = '#ffffff';
      g.fill();
      g.lineWidth = 5;
      g.strokeStyle = '#0b0d12';
      g.stroke();
    }
    return new THREE.CanvasTexture(c);
  }
  var disc = sprite(false), verdictColours = {1: 0x26d9c7, 2: 0xff4060, 3: 0xc77dff}, counts = [];
  [2, 3, 1].forEach(function (verdict, order) {
    var at = [];
    for (var i = 0; i < steps.count; ++i) {
      var q = 3 * steps.pose[i];
      if (steps.verdict[i] === verdict && isFinite(poses[q]) && isFinite(poses[q + 1]) && isFinite(poses[q + 2]))
        at.push(poses[q], poses[q + 1], poses[q + 2]);
    }
    counts[verdict] = at.length / 3;
    if (!at.length) return;
    layers['marker' + verdict] = points(new Float32Array(at), null, new THREE.PointsMaterial({
      size: 9, map: disc, color: verdictColours[verdict], transparent: true, alphaTest: 0.4,
      depthTest: false, sizeAttenuation: false}), 5 - order);
  });
  body.setAttribute('data-sx-markers', [counts[2], counts[3], counts[1]].join(','));
  var selection = points(new Float32Array(3), null, new THREE.PointsMaterial({
    size: 24, map: sprite(true), color: 0xffffff, transparent: true, alphaTest: 0.3, depthTest: false,
    sizeAttenuation: false}), 9);
  selection.visible = false;

  // Cameras: the orbit (perspective, z up) and the top view (orthographic, looking down, north up).
  var perspective = new THREE.PerspectiveCamera(45, 1, 0.01, 1000), top = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
  perspective.up.set(0, 0, 1);
  top.up.set(0, 1, 0);
  var halfFov = perspective.fov * Math.PI / 360, orbit = {}, topView = false, pending = false;
  function camera() { return topView ? top : perspective; }
  // The part of the window the panels leave free: the scene is centred there and fits its width.
  var panels = [document.getElementById('sx-panel'), document.getElementById('sx-side')];
  function free() {
    var w = window.innerWidth, left = panels[0].getBoundingClientRect().right, right = panels[1].getBoundingClientRect().left;
    if (!(right - left > 0.3 * w)) left = 0, right = w;
    return {shift: (left + right) / 2 - w / 2, fit: Math.max(1, window.innerHeight / Math.max(right - left, 1))};
  }
  function draw() {
    pending = false;
    var w = window.innerWidth, h = window.innerHeight, t = orbit.target;
    if (w !== width || h !== height) {
      width = w, height = h;
      renderer.setSize(w, h, false);
      lineMaterials.forEach(function (material) { material.resolution.set(w, h); });
    }
    var area = free();
    camera().setViewOffset(w, h, -area.shift, 0, w, h);
    if (topView) {
      var half = orbit.half, aspect = w / Math.max(h, 1);
      top.left = -half * aspect, top.right = half * aspect, top.top = half, top.bottom = -half;
      top.position.set(t.x, t.y, t.z + 2 * extent);
      top.near = 0.01 * extent, top.far = 4 * extent;
      top.lookAt(t.x, t.y, t.z);
      top.updateProjectionMatrix();
      top.updateMatrixWorld();
    } else {
      var ce = Math.cos(orbit.elevation);
      perspective.aspect = w / Math.max(h, 1);
      perspective.position.set(t.x + orbit.distance * ce * Math.cos(orbit.azimuth),
                               t.y + orbit.distance * ce * Math.sin(orbit.azimuth),
                               t.z + orbit.distance * Math.sin(orbit.elevation));
      perspective.lookAt(t);
      perspective.far = perspective.position.length() + 2 * extent;
      perspective.near = Math.max(perspective.far * 1e-5, orbit.distance * 1e-3);
      perspective.updateProjectionMatrix();
      perspective.updateMatrixWorld();
    }
    renderer.render(scene, camera());
  }
  function redraw() {
    if (!pending) {
      pending = true;
      requestAnimationFrame(draw);
    }
  }
  function reset() {
    orbit.target = new THREE.Vector3(0, 0, 0);
    orbit.azimuth = -Math.PI / 2 - 0.5;
    orbit.elevation = 0.75;
    var fit = free().fit;
    orbit.distance = 1.05 * fit * radius / Math.sin(halfFov);
    orbit.half = 1.05 * fit * radius;
    redraw();
  }
  var buttons = {top: document.getElementById('sx-top'), orbit: document.getElementById('sx-3d')};
  function setTop(on) {
    topView = on;
    buttons.top.className = on ? 'sx-on' : '';
    buttons.orbit.className = on ? '' : 'sx-on';
    redraw();
  }
  buttons.top.addEventListener('click', function () { setTop(true); });
  buttons.orbit.addEventListener('click', function () { setTop(false); });
  document.getElementById('sx-reset').addEventListener('click', reset);
  Array.prototype.forEach.call(document.querySelectorAll('input[data-layer]'), function (input) {
    input.addEventListener('change', function () {
      var layer = layers[input.getAttribute('data-layer')];
      if (layer) layer.visible = input.checked;
      redraw();
    });
  });
  if (byError && layers.estimate)
    byError.addEventListener('change', function () {
      layers.estimate.geometry.setColors(estimateColours(byError.checked));
      redraw();
    });
  var slider = document.getElementById('sx-size');
  function size() {
    if (layers.map) layers.map.material.size = parseFloat(slider.value);
    redraw();
  }
  slider.addEventListener('input', size);

  // The selected step: the ring at its pose; focus moves the view's centre there.
  hooks.select = function (i, focus) {
    var q = 3 * steps.pose[i], at = new THREE.Vector3(poses[q], poses[q + 1], poses[q + 2]);
    if (!isFinite(at.x + at.y + at.z)) return (selection.visible = false), redraw();
    selection.geometry.attributes.position.setXYZ(0, at.x, at.y, at.z);
    selection.geometry.attributes.position.needsUpdate = true;
    selection.geometry.computeBoundingSphere();
    selection.visible = true;
    if (focus) orbit.target.copy(at);
    redraw();
  };
  function pick(x, y) {
    var rect = canvas.getBoundingClientRect(), v = new THREE.Vector3(), best = -1, bestD = 14 * 14, bestMarked = false;
    camera().updateMatrixWorld();
    for (var k = 0; k < stepAt.length; ++k) {
      var i = stepAt[k];
      if (i < 0 || !isFinite(poses[3 * k])) continue;
      v.set(poses[3 * k], poses[3 * k + 1], poses[3 * k + 2]).project(camera());
      if (v.z < -1 || v.z > 1) continue;
      var dx = (v.x + 1) / 2 * rect.width - (x - rect.left), dy = (1 - v.y) / 2 * rect.height - (y - rect.top);
      var d = dx * dx + dy * dy, marked = steps.verdict[i] >= 1 && steps.verdict[i] <= 3;
      if (d > 14 * 14) continue;
      if ((marked && !bestMarked) || (marked === bestMarked && d < bestD)) best = i, bestD = d, bestMarked = marked;
    }
    if (best >= 0) panel.select(best, false);
  }

  var drag = null;
  canvas.addEventListener('contextmenu', function (e) { e.preventDefault(); });
  canvas.addEventListener('pointerdown', function (e) {
    drag = {x: e.clientX, y: e.clientY, x0: e.clientX, y0: e.clientY, pan: topView || e.button !== 0 || e.shiftKey || e.ctrlKey};
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', function (e) {
    if (!drag) return;
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX, drag.y = e.clientY;
    if (drag.pan) {
      var scale = (topView ? 2 * orbit.half : 2 * orbit.distance * Math.tan(halfFov)) / Math.max(canvas.clientHeight, 1);
      var right = new THREE.Vector3().setFromMatrixColumn(camera().matrixWorld, 0);
      var up = new THREE.Vector3().setFromMatrixColumn(camera().matrixWorld, 1);
      orbit.target.addScaledVector(right, -dx * scale).addScaledVector(up, dy * scale);
    } else {
      orbit.azimuth -= dx * 0.006;
      orbit.elevation = Math.max(-1.55, Math.min(1.55, orbit.elevation + dy * 0.006));
    }
    redraw();
  });
  canvas.addEventListener('pointerup', function (e) {
    if (drag && Math.abs(e.clientX - drag.x0) + Math.abs(e.clientY - drag.y0) < 5 && e.button === 0) pick(e.clientX, e.clientY);
    drag = null;
  });
  canvas.addEventListener('pointercancel', function () { drag = null; });
  canvas.addEventListener('wheel', function (e) {
    e.preventDefault();
    var unit = e.deltaMode === 1 ? 40 : e.deltaMode === 2 ? 800 : 1, f = Math.exp(e.deltaY * unit * 0.0015);
    orbit.distance = Math.max(radius * 1e-3, Math.min(extent * 20, orbit.distance * f));
    orbit.half = Math.max(radius * 1e-3, Math.min(extent * 20, orbit.half * f));
    redraw();
  }, {passive: false});
  canvas.addEventListener('dblclick', reset);
  window.addEventListener('keydown', function (e) {
    if (e.ctrlKey || e.altKey || e.metaKey || e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
    if (e.key === 'r' || e.key === 'R') reset();
    if (e.key === 't' || e.key === 'T') setTop(true);
    if (e.key === '3') setTop(false);
  });
  window.addEventListener('resize', redraw);

  reset();
  setTop(/(^|[#&])top\b/.test(window.location.hash));
  size();
  var asked = /step=(\d+)/.exec(window.location.hash);
  if (asked) panel.select(panel.byNumber(parseInt(asked[1], 10)), true);
  draw();
  // What the first frame painted: pixels off the background, of the estimate's amber, of the untrusted red.
  var gl = renderer.getContext(), pw = gl.drawingBufferWidth, ph = gl.drawingBufferHeight, px = new Uint8Array(4 * pw * ph);
  gl.readPixels(0, 0, pw, ph, gl.RGBA, gl.UNSIGNED_BYTE, px);
  var painted = [0, 0, 0];
  function near(i, r, g, b, d) { return Math.abs(px[i] - r) + Math.abs(px[i + 1] - g) + Math.abs(px[i + 2] - b) <= d; }
  for (var i = 0; i < px.length; i += 4) {
    if (!near(i, 15, 18, 24, 24)) ++painted[0];
    if (near(i, 255, 176, 32, 40)) ++painted[1];
    if (near(i, 255, 64, 96, 40)) ++painted[2];
  }
  body.setAttribute('data-sx-painted', painted.join(','));
  say('');
  body.setAttribute('data-sx-drawn', 'ok');
})();
)JS";
}

}  // namespace sextant::detail
