// The interactive wall's HTML: the frames as JSON with base64 float arrays, three.js and
// its OrbitControls inlined from Debian's libjs-three, and the page's own script (below),
// which draws the wall, recolours it, and moves the trace's cursor with the slider.
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "vesica/compare/html/SvgPlot.h"
#include "vesica/compare/html/Viridis.h"
#include "vesica/compare/report/WallStressPicture.h"
#include "vesica/compare/report/WallViewer.h"

namespace vesica::compare {
namespace {

template <typename T>
std::string packed(const std::vector<T>& values) {
  return base64(
      std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
}

std::string text_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// "</script" inside an inlined library would end the element early.
std::string script_safe(std::string js) {
  for (std::size_t at = js.find("</script"); at != std::string::npos; at = js.find("</script", at))
    js.replace(at, 2, "<\\/");
  return js;
}

nlohmann::json viewer_json(const WallViewer& v) {
  nlohmann::json frames = nlohmann::json::array();
  for (const WallViewerFrame& f : v.frames) {
    frames.push_back({{"time_s", f.time_s},
                      {"axis_s", f.time_s - v.axis_start_s},
                      {"volume_ml", f.volume_ml},
                      {"pdet_cmh2o", f.pdet_cmh2o},
                      {"points", packed(f.points_mm)},
                      {"sigma1", packed(f.sigma1_kpa)},
                      {"stretch", packed(f.stretch)}});
    if (f.urine_triangles.empty()) continue;
    frames.back()["urine_points"] = packed(f.urine_points_mm);
    frames.back()["urine_triangles"] = packed(f.urine_triangles);
    frames.back()["urine_speed"] = packed(f.urine_speed_m_s);
  }
  nlohmann::json palette = nlohmann::json::array();
  for (int i = 0; i <= 64; ++i) {
    const auto rgb = viridis(i / 64.0);
    palette.push_back({rgb[0], rgb[1], rgb[2]});
  }
  nlohmann::json ranges = {{"sigma1", {v.sigma1_range_kpa[0], v.sigma1_range_kpa[1]}},
                           {"stretch", {v.stretch_range[0], v.stretch_range[1]}}};
  if (v.has_urine)
    ranges["speed"] = {0.0, v.urine_speed_max_m_s > 0.0 ? v.urine_speed_max_m_s : 1e-6};
  return {{"triangles", packed(v.triangles)},
          {"urine_normal", {v.urine_normal[0], v.urine_normal[1], v.urine_normal[2]}},
          {"frames", frames},
          {"capacity_frame", v.capacity_frame},
          {"ranges", ranges},
          {"palette", palette},
          {"nan", {0.6, 0.6, 0.6}},
          {"below", {0.0, 0.0, 0.0}},
          {"above", {1.0, 0.35, 0.7}}};
}

// The page's script: plain ES5 over the global THREE, so that it runs from file:// with no
// module loader.
const char* kViewerScript = R"JS(
(function () {
  var data = JSON.parse(document.getElementById('wall3d-data').textContent);
  function floats(b64, Type) {
    var s = atob(b64), bytes = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) bytes[i] = s.charCodeAt(i);
    return new Type(bytes.buffer);
  }
  var tri = floats(data.triangles, Int32Array), m = tri.length / 3;
  var frames = data.frames.map(function (f) {
    return {f: f, points: floats(f.points, Float32Array), sigma1: floats(f.sigma1, Float32Array),
            stretch: floats(f.stretch, Float32Array),
            urine: f.urine_triangles ? {points: floats(f.urine_points, Float32Array),
                                        index: new Uint32Array(floats(f.urine_triangles, Int32Array)),
                                        speed: floats(f.urine_speed, Float32Array)} : null};
  });
  var canvas = document.getElementById('wall3d-canvas');
  var renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(1);
  renderer.setSize(canvas.clientWidth || 640, canvas.clientHeight || 480, false);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  var geometry = new THREE.BufferGeometry();
  var position = new Float32Array(9 * m), colour = new Float32Array(9 * m);
  geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colour, 3));
  var wall = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial(
      {vertexColors: THREE.VertexColors || true, side: THREE.DoubleSide}));
  scene.add(wall);
  // Level 2: the urine's section through the outlet axis, drawn inside a faint wall.
  var urineGeometry = new THREE.BufferGeometry();
  var urine = new THREE.Mesh(urineGeometry, new THREE.MeshBasicMaterial(
      {vertexColors: THREE.VertexColors || true, side: THREE.DoubleSide}));
  urine.visible = false;
  scene.add(urine);
  var camera = new THREE.PerspectiveCamera(30, canvas.width / canvas.height, 1, 1e5);
  var controls = new THREE.OrbitControls(camera, canvas);
  controls.addEventListener('change', draw);

  function colourOf(v, range) {
    if (!isFinite(v)) return data.nan;
    if (v < range[0]) return data.below;
    if (v > range[1]) return data.above;
    var x = (v - range[0]) / (range[1] - range[0]) * (data.palette.length - 1);
    var k = Math.min(Math.floor(x), data.palette.length - 2), t = x - k;
    var a = data.palette[k], b = data.palette[k + 1];
    return [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])];
  }
  var slider = document.getElementById('wall3d-time'), choice = document.getElementById('wall3d-quantity');
  var label = document.getElementById('wall3d-label'), bar = document.getElementById('wall3d-bar');
  function draw() { renderer.render(scene, camera); }
  function fixed(v, digits) { return typeof v === 'number' ? v.toFixed(digits) : '?'; }
  var faint = [0.75, 0.75, 0.75];
  function showUrine(fr, on) {
    wall.material.transparent = on;
    wall.material.opacity = on ? 0.15 : 1;
    wall.material.depthWrite = !on;
    wall.material.needsUpdate = true;
    urine.visible = on && !!fr.urine;
    if (!urine.visible) return;
    var u = fr.urine, n = u.speed.length, c = new Float32Array(3 * n);
    for (var i = 0; i < n; ++i) {
      var rgb = colourOf(u.speed[i], data.ranges.speed);
      for (var d = 0; d < 3; ++d) c[3 * i + d] = rgb[d];
    }
    urineGeometry.setAttribute('position', new THREE.BufferAttribute(u.points, 3));
    urineGeometry.setAttribute('color', new THREE.BufferAttribute(c, 3));
    urineGeometry.setIndex(new THREE.BufferAttribute(u.index, 1));
    urineGeometry.computeBoundingSphere();
  }
  function barText(q, range, fr) {
    if (q === 'speed')
      return 'urine speed |u| (m/s) 0 to ' + range[1].toPrecision(3) +
          ' on the plane through the outlet axis, the wall drawn faint' +
          (fr.urine ? '' : ' (no fluid frame at this time)');
    return (q === 'sigma1' ? 'sigma1 (kPa) ' : 'larger principal stretch ') +
        range[0].toPrecision(3) + ' to ' + range[1].toPrecision(3) +
        ' (2nd to 98th percentile; below black, above pink; outlet grey)';
  }
  function show(i) {
    var fr = frames[i], q = choice.value, range = data.ranges[q];
    var values = q === 'speed' ? null : fr[q];
    showUrine(fr, q === 'speed');
    for (var t = 0; t < m; ++t) {
      var c = values ? colourOf(values[t], range) : faint;
      for (var k = 0; k < 3; ++k) {
        var n = tri[3 * t + k];
        for (var d = 0; d < 3; ++d) {
          position[9 * t + 3 * k + d] = fr.points[3 * n + d];
          colour[9 * t + 3 * k + d] = c[d];
        }
      }
    }
    geometry.attributes.position.needsUpdate = true;
    geometry.attributes.color.needsUpdate = true;
    geometry.computeBoundingSphere();
    var f = fr.f;
    label.textContent = (i === data.capacity_frame ? 'nearest capacity: ' : '') + 't = ' +
        f.time_s.toFixed(0) + ' s, V = ' + fixed(f.volume_ml, 0) + ' ml, Pdet = ' +
        fixed(f.pdet_cmh2o, 1) + ' cmH2O';
    bar.textContent = barText(q, range, fr);
    moveCursor(f.axis_s);
    draw();
  }
  function moveCursor(t) {
    var svg = document.getElementById('plot-trace'), line = document.getElementById('plot-trace-cursor');
    if (!svg || !line) return;
    var lo = +svg.dataset.tLo, hi = +svg.dataset.tHi, x0 = +svg.dataset.xLo, x1 = +svg.dataset.xHi;
    if (!(hi > lo)) return;
    var x = x0 + (Math.min(Math.max(t, lo), hi) - lo) / (hi - lo) * (x1 - x0);
    line.setAttribute('x1', x);
    line.setAttribute('x2', x);
    line.setAttribute('visibility', 'visible');
  }
  // Anterior view, as the static picture: camera on -y (LPS), head (+z) up.
  var p = frames[data.capacity_frame].points, lo = [1e9, 1e9, 1e9], hi = [-1e9, -1e9, -1e9];
  for (var i = 0; i < p.length; ++i) { lo[i % 3] = Math.min(lo[i % 3], p[i]); hi[i % 3] = Math.max(hi[i % 3], p[i]); }
  var centre = new THREE.Vector3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  var size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  camera.up.set(0, 0, 1);
  camera.position.set(centre.x, centre.y - 2.6 * size, centre.z);
  controls.target.copy(centre);
  controls.update();
  slider.max = frames.length - 1;
  slider.value = data.capacity_frame;
  slider.addEventListener('input', function () { show(+slider.value); });
  // The urine's section is seen face on; the wall's quantities from the front again.
  choice.addEventListener('change', function () {
    var n = choice.value === 'speed' ? data.urine_normal : [0, 1, 0];
    camera.position.set(centre.x - 2.6 * size * n[0], centre.y - 2.6 * size * n[1],
                        centre.z - 2.6 * size * n[2]);
    controls.update();
    show(+slider.value);
  });
  show(data.capacity_frame);

  // What a headless browser's DOM dump can check: how much of the canvas is drawn, and,
  // with #check-slider in the address, where the slider's ends put the trace's cursor.
  function record(prefix) {
    var line = document.getElementById('plot-trace-cursor');
    document.body.dataset[prefix + 'Cursor'] = line ? line.getAttribute('x1') : '';
    document.body.dataset[prefix + 'Label'] = label.textContent;
  }
  function ink() {
    var gl = renderer.getContext(), w = canvas.width, h = canvas.height, px = new Uint8Array(4 * w * h);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    var inked = 0;
    for (var j = 0; j < w * h; ++j) if (px[4 * j] + px[4 * j + 1] + px[4 * j + 2] < 720) ++inked;
    return (inked / (w * h)).toFixed(3);
  }
  document.body.dataset.wall3dInk = ink();
  record('wall3dCapacity');
  // The urine's section at its fastest frame: drawn (ink), and its colour bar's range.
  if (data.ranges.speed && location.hash === '#check-urine') {
    var fastest = 0, top = -1;
    frames.forEach(function (fr, i) {
      if (!fr.urine) return;
      for (var k = 0; k < fr.urine.speed.length; ++k)
        if (fr.urine.speed[k] > top) { top = fr.urine.speed[k]; fastest = i; }
    });
    document.body.dataset.wall3dUrineFrames = frames.filter(function (fr) { return fr.urine; }).length;
    choice.value = 'speed';
    choice.dispatchEvent(new Event('change'));
    slider.value = fastest;
    slider.dispatchEvent(new Event('input'));
    document.body.dataset.wall3dUrineInk = ink();
    document.body.dataset.wall3dUrineBar = bar.textContent;
  }
  if (location.hash === '#check-slider') {
    slider.value = 0;
    slider.dispatchEvent(new Event('input'));
    record('wall3dFirst');
    slider.value = frames.length - 1;
    slider.dispatchEvent(new Event('input'));
    record('wall3dLast');
  }
})();
)JS";

}  // namespace

std::string wall_viewer_section(const WallViewer& v, const std::filesystem::path& three_js_dir) {
  if (v.frames.empty()) return "<p class=\"missing\">" + xml_escape(v.message) + "</p>\n";
  const auto three = three_js_dir / "three.min.js";
  const auto orbit = three_js_dir / "examples/js/controls/OrbitControls.js";
  if (!std::filesystem::exists(three) || !std::filesystem::exists(orbit))
    return "<p class=\"missing\">No interactive view: three.js was not found in " +
           xml_escape(three_js_dir.string()) +
           " (Debian's libjs-three); the picture above shows the wall at capacity.</p>\n";
  std::ostringstream o;
  o << "<div class=\"wall3d\"><canvas id=\"wall3d-canvas\" width=\"640\" height=\"480\" "
       "style=\"width:640px;max-width:100%;height:480px;border:1px solid #ddd\"></canvas>\n"
    << "<div class=\"controls\"><label>colour <select id=\"wall3d-quantity\">"
       "<option value=\"sigma1\">&sigma;1, max principal Cauchy stress (kPa)</option>"
       "<option value=\"stretch\">larger principal stretch</option>"
    << (v.has_urine ? "<option value=\"speed\">urine speed through the outlet axis (m/s)</option>"
                    : "")
    << "</select></label> "
    << "<label>time <input id=\"wall3d-time\" type=\"range\" min=\"0\" step=\"1\" "
       "style=\"width:320px;max-width:100%\"></label>\n"
    << "<p id=\"wall3d-label\" class=\"small\"></p><p id=\"wall3d-bar\" class=\"small\"></p>"
       "</div>\n"
    << "<p class=\"note\">Drag to turn the wall, scroll to zoom; the slider runs over "
    << v.frames.size()
    << " frames of filling and voiding and moves the red cursor on the trace above. The "
       "wall is drawn from the simulation's series (series.pvd)"
    << (v.has_urine ? ", the urine's section from its fluid series (fluid.pvd)" : "")
    << " and opens with no network.</p>\n"
    << "<script type=\"application/json\" id=\"wall3d-data\">" << script_safe(viewer_json(v).dump())
    << "</script>\n"
    << "<script>" << script_safe(text_of(three)) << "</script>\n"
    << "<script>" << script_safe(text_of(orbit)) << "</script>\n"
    << "<script>" << kViewerScript << "</script></div>\n";
  return o.str();
}

}  // namespace vesica::compare
