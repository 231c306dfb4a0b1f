// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_PAGE_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_PAGE_H

// The fixed parts of the page of write_HTML_viewer(): its style sheet, the
// script that records every error into the page, and the viewer's script,
// which reads the data block (JSON, arrays in base64) and draws the layers
// with three.js r111. The data and the three.js files are spliced in between
// by html_viewer_text().

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// The style sheet, in the head of the page.
inline const char* html_viewer_style()
{
  static const char* const text =
    R"PVF(<style>
html, body { margin: 0; height: 100%; overflow: hidden; font: 14px/1.35 sans-serif; color: #202020; background: #fff; }
#pvf-canvas { display: block; }
#pvf-panel { position: absolute; top: 10px; left: 10px; max-width: 46%; padding: 8px 12px;
             background: rgba(255, 255, 255, 0.88); border: 1px solid #ccc; border-radius: 4px; }
#pvf-panel h1 { font-size: 15px; margin: 0 0 6px 0; }
#pvf-layers label { display: block; cursor: pointer; }
#pvf-help { margin-top: 6px; color: #666; font-size: 12px; }
#pvf-colour-bar { display: none; position: absolute; right: 24px; top: 240px;
                  padding: 8px; background: rgba(255, 255, 255, 0.88); border: 1px solid #ccc; border-radius: 4px; }
#pvf-colour-bar .pvf-bar-body { position: relative; height: 260px; width: 110px; }
#pvf-colour-ramp { position: absolute; left: 0; top: 0; width: 26px; height: 260px; border: 1px solid #888; }
#pvf-colour-bar span { position: absolute; left: 34px; font-size: 12px; white-space: nowrap; }
#pvf-colour-top { top: -7px; }
#pvf-colour-middle { top: 123px; }
#pvf-colour-bottom { bottom: -7px; }
#pvf-colour-bar .pvf-bar-caption { text-align: center; font-size: 12px; margin-bottom: 10px; }
#pvf-errors { display: none; position: absolute; left: 0; right: 0; bottom: 0; margin: 0; padding: 8px;
              color: #a00000; background: #fff0f0; white-space: pre-wrap; }
</style>
)PVF";
  return text;
}

// The first script of the page: every error is written into the element pvf-errors
// and counted in the attribute data-errors of pvf-status.
inline const char* html_viewer_error_script()
{
  static const char* const text =
    R"PVF((function () {
  'use strict';
  // Every error of the page is written into it: window errors, rejected
  // promises and console.error (three.js reports WebGL failures there).
  var count = 0;
  function record(text) {
    var pre = document.getElementById('pvf-errors');
    pre.style.display = 'block';
    pre.textContent += text + '\n';
    document.getElementById('pvf-status').setAttribute('data-errors', String(++count));
  }
  window.addEventListener('error', function (event) {
    record('error: ' + event.message + (event.lineno ? ' (line ' + event.lineno + ')' : ''));
  });
  window.addEventListener('unhandledrejection', function (event) { record('unhandled rejection: ' + event.reason); });
  var original = console.error;
  console.error = function () {
    record('console.error: ' + Array.prototype.join.call(arguments, ' '));
    return original.apply(console, arguments);
  };
})();
)PVF";
  return text;
}

// The viewer, run once three.js, OrbitControls and the data block are in the page.
inline const char* html_viewer_script()
{
  // In pieces of less than 16 KB: the longest string literal some compilers accept.
  static const char* const text =
    R"PVF((function () {
  'use strict';
  var status = document.getElementById('pvf-status');
  var data = JSON.parse(document.getElementById('pvf-data').textContent);

  // Base64 of little-endian arrays, as the writer encodes them.
  function bytes(text) {
    var s = atob(text), a = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i);
    return a.buffer;
  }
  function floats(text) { return new Float32Array(bytes(text)); }
  function uints(text) { return new Uint32Array(bytes(text)); }
  function ints(text) { return new Int32Array(bytes(text)); }
  function rgb(c) { return new THREE.Color(c[0] / 255, c[1] / 255, c[2] / 255); }

  // Options of the address: #layers=quads,singularities&view=worst
  var hash = {};
  window.location.hash.replace(/^#/, '').split('&').forEach(function (item) {
    var kv = item.split('=');
    if (kv[0]) hash[kv[0]] = kv.length > 1 ? decodeURIComponent(kv[1]) : '';
  });

  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.domElement.id = 'pvf-canvas';
  document.body.insertBefore(renderer.domElement, document.body.firstChild);

  // The surface: positions are relative to the centre of its bounding box.
  var positions = floats(data.surface.vertices);
  var triangles = uints(data.surface.triangles);
  var radius = data.surface.radius, meanEdge = data.surface.mean_edge;
  var camera = new THREE.PerspectiveCamera(30, window.innerWidth / window.innerHeight, radius / 500, radius * 50);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));
  // A light that follows the camera, from slightly above and to the left.
  var light = new THREE.DirectionalLight(0xffffff, 0.6);
  light.position.set(-0.25, 0.35, 0);
  light.target.position.set(0, 0, -1);
  camera.add(light);
  camera.add(light.target);
  scene.add(camera);

  var layers = {};   // name -> { object, label, shown }
  function addLayer(name, object, label, shown) {
    layers[name] = { object: object, label: label, shown: shown };
    scene.add(object);
  }

  var surfaceGeometry = new THREE.BufferGeometry();
  surfaceGeometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  surfaceGeometry.setIndex(new THREE.BufferAttribute(triangles, 1));
  surfaceGeometry.computeVertexNormals();
  var hasQuads = !!data.quads;
  addLayer('surface', new THREE.Mesh(surfaceGeometry, new THREE.MeshLambertMaterial({
    color: 0xd0d0d0, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1
  })), 'surface (' + data.surface.faces + ' triangles)', !hasQuads);

  function centroid(f) {
    var c = [0, 0, 0];
    for (var k = 0; k < 3; ++k)
      for (var j = 0; j < 3; ++j) c[j] += positions[3 * triangles[3 * f + k] + j] / 3;
    return c;
  }

  // The field: N line glyphs from the centroid of each drawn face.
  if (data.field) {
    // A sign-symmetric field stores one vector of each pair {u, -u}: a line through the centroid.
    var glyphFaces = uints(data.field.faces), vectors = new Int16Array(bytes(data.field.vectors));
    var N = data.field.N, symmetric = data.field.symmetric, stored = symmetric ? N / 2 : N;
    var scale = data.field.scale, segments = new Float32Array(glyphFaces.length * stored * 6);
    for (var g = 0; g < glyphFaces.length; ++g) {
      var c = centroid(glyphFaces[g]);
      for (var k = 0; k < stored; ++k)
        for (var j = 0; j < 3; ++j) {
          var o = 6 * (g * stored + k), u = scale * vectors[3 * (g * stored + k) + j];
          segments[o + j] = symmetric ? c[j] - u : c[j];
          segments[o + 3 + j] = c[j] + u;
        }
    }
    var fieldGeometry = new THREE.BufferGeometry();
    fieldGeometry.setAttribute('position', new THREE.BufferAttribute(segments, 3));
    addLayer('field', new THREE.LineSegments(fieldGeometry, new THREE.LineBasicMaterial({ color: 0x1a1a60 })),
             'field (' + N + ' vectors per face' +
             (data.field.stride > 1 ? ', on 1 face in ' + data.field.stride : '') + ')', !hasQuads);
  }

  // The constrained faces, drawn over the surface.
  if (data.constrained) {
    var constrained = uints(data.constrained), index = new Uint32Array(3 * constrained.length);
    for (var i = 0; i < constrained.length; ++i)
      for (var k = 0; k < 3; ++k) index[3 * i + k] = triangles[3 * constrained[i] + k];
    var constrainedGeometry = new THREE.BufferGeometry();
    constrainedGeometry.setAttribute('position', surfaceGeometry.getAttribute('position'));
    constrainedGeometry.setAttribute('normal', surfaceGeometry.getAttribute('normal'));
    constrainedGeometry.setIndex(new THREE.BufferAttribute(index, 1));
    addLayer('constraints', new THREE.Mesh(constrainedGeometry, new THREE.MeshLambertMaterial({
      color: 0xf08c28, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1
    })), 'constrained faces (' + constrained.length + ')', !hasQuads);
  }

  // The singularities: a ball on each singular vertex, red for a positive
  // index and blue for a negative one, larger for a larger |index|.
  if (data.singularities) {
    var singular = uints(data.singularities.vertices), numerators = ints(data.singularities.numerators);
    var group = new THREE.Group(), ball = new THREE.SphereBufferGeometry(1, 12, 8);
    var materials = {};
    for (var i = 0; i < singular.length; ++i) {
      var n = numerators[i], key = n > 0 ? 'p' : 'n';
      if (!materials[key])
        materials[key] = new THREE.MeshLambertMaterial({ color: n > 0 ? 0xe0201c : 0x2060e0 });
      var m = new THREE.Mesh(ball, materials[key]);
      var v = singular[i], r = 0.6 * meanEdge * Math.sqrt(Math.min(Math.abs(n), 4));
      m.position.set(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      m.scale.set(r, r, r);
      group.add(m);
    }
    addLayer('singularities', group, 'singularities (' + singular.length + ': red positive, blue negative)', true);
  }

  // The quad mesh, each face coloured by its planarity, with its edges.
  var worst = null;
  if (hasQuads) {
    var q = data.quads, qp = floats(q.vertices), sizes = uints(q.sizes), qi = uints(q.indices);
    var planarity = floats(q.planarity), colours = uints(q.colours);
    var triangleCount = 0, edgeCount = 0;
    for (var f = 0; f < sizes.length; ++f) { triangleCount += sizes[f] - 2; edgeCount += sizes[f]; }
    var tp = new Float32Array(9 * triangleCount), tc = new Float32Array(9 * triangleCount);
    var ep = new Float32Array(6 * edgeCount);
    var t = 0, e = 0, start = 0;
    function put(array, at, v) { for (var j = 0; j < 3; ++j) array[at + j] = qp[3 * v + j]; }
    for (var f = 0; f < sizes.length; ++f) {
      var s = sizes[f], colour = colours[f];
      var cr = ((colour >> 16) & 255) / 255, cg = ((colour >> 8) & 255) / 255, cb = (colour & 255) / 255;
      for (var k = 1; k + 1 < s; ++k, ++t) {
        var corner = [qi[start], qi[start + k], qi[start + k + 1]];
        for (var l = 0; l < 3; ++l) {
          put(tp, 9 * t + 3 * l, corner[l]);
          tc[9 * t + 3 * l] = cr; tc[9 * t + 3 * l + 1] = cg; tc[9 * t + 3 * l + 2] = cb;
        }
      }
      for (var k = 0; k < s; ++k, ++e) {
        put(ep, 6 * e, qi[start + k]);
        put(ep, 6 * e + 3, qi[start + (k + 1) % s]);
      }
      if (s === 4 && (worst === null || planarity[f] > worst.planarity))
        worst = { face: f, planarity: planarity[f], corners: [qi[start], qi[start + 1], qi[start + 2], qi[start + 3]] };
      start += s;
    }
    var quadGeometry = new THREE.BufferGeometry();
    quadGeometry.setAttribute('position', new THREE.BufferAttribute(tp, 3));
    quadGeometry.setAttribute('color', new THREE.BufferAttribute(tc, 3));
    quadGeometry.computeVertexNormals();
    var quadGroup = new THREE.Group();
    quadGroup.add(new THREE.Mesh(quadGeometry, new THREE.MeshLambertMaterial({
      vertexColors: THREE.VertexColors, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1,
      polygonOffsetUnits: 1
    })));
    var edgeGeometry = new THREE.BufferGeometry();
    edgeGeometry.setAttribute('position', new THREE.BufferAttribute(ep, 3));
    quadGroup.add(new THREE.LineSegments(edgeGeometry, new THREE.LineBasicMaterial({ color: 0x303030 })));
    addLayer('quads', quadGroup, 'quad mesh (' + q.quads + ' quads, coloured by planarity)', true);
  }

  // Layers asked for in the address replace the defaults.
  if (hash.layers !== undefined) {
    var asked = hash.layers.split(',');
    for (var name in layers) layers[name].shown = asked.indexOf(name) >= 0;
  }

  // The camera: an oblique view of the whole surface, y up, or z up when the
  // bounding box is flat along z (a roof, a terrain); or, with view=worst,
  // straight at the quad of largest planarity.
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  var extent = data.surface.extent;
  var zUp = extent[2] < 0.6 * Math.min(extent[0], extent[1]);
  camera.up.set(0, zUp ? 0 : 1, zUp ? 1 : 0);
  var direction = zUp ? new THREE.Vector3(0.45, -1, 0.75) : new THREE.Vector3(0.45, 0.6, 1);
  var distance = radius / Math.sin(camera.fov * Math.PI / 360) * 0.85;
  // The surface a little below the middle, clear of the panel of layers.
  controls.target.copy(camera.up).multiplyScalar(0.06 * radius);
  if (hash.view === 'worst' && worst) {
    var p = worst.corners.map(function (v) { return new THREE.Vector3(qp[3 * v], qp[3 * v + 1], qp[3 * v + 2]); });
    var centre = p[0].clone().add(p[1]).add(p[2]).add(p[3]).multiplyScalar(0.25);
    var d1 = p[2].clone().sub(p[0]), d2 = p[3].clone().sub(p[1]);
    var normal = d1.clone().cross(d2).normalize();
    direction = normal;
    distance = 6 * Math.max(d1.length(), d2.length());
    controls.target.copy(centre);
  }
  camera.position.copy(controls.target).add(direction.normalize().multiplyScalar(distance));
  camera.lookAt(controls.target);
  controls.update();

  function render() { renderer.render(scene, camera); }
  controls.addEventListener('change', render);
  window.addEventListener('resize', function () {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    render();
  });

  // The colour bar goes with the quad mesh.
  function showColourBar(shown) { document.getElementById('pvf-colour-bar').style.display = shown ? 'block' : 'none'; }

  // One check box per layer.
  var panel = document.getElementById('pvf-layers');
  Object.keys(layers).forEach(function (name) {
    var layer = layers[name], row = document.createElement('label'), box = document.createElement('input');
    box.type = 'checkbox';
    box.id = 'pvf-layer-' + name;
    box.checked = layer.shown;
    layer.object.visible = layer.shown;
    box.addEventListener('change', function () {
      layer.object.visible = box.checked;
      if (name === 'quads') showColourBar(box.checked);
      render();
    });
    row.appendChild(box);
    row.appendChild(document.createTextNode(' ' + layer.label));
    panel.appendChild(row);
  });

  // The colour bar of the planarity, from the writer's stops.
  if (hasQuads) {
    showColourBar(layers.quads.shown);
    var stops = data.quads.colour_stops.map(function (s) {
      return 'rgb(' + s[1] + ',' + s[2] + ',' + s[3] + ') ' + (100 * s[0]) + '%';
    });
    document.getElementById('pvf-colour-ramp').style.background = 'linear-gradient(to top, ' + stops.join(', ') + ')';
    document.getElementById('pvf-colour-top').textContent = (100 * data.quads.range).toPrecision(3) + '%' +
      (data.quads.range < data.quads.max ? ' and above' : '');
    document.getElementById('pvf-colour-middle').textContent = (50 * data.quads.range).toPrecision(3) + '%';
  }

  render();
  // What was drawn, for the tests (and anyone curious).
)PVF"
    R"PVF(  if (hasQuads && layers.quads.shown) {
    var r = document.getElementById('pvf-colour-ramp').getBoundingClientRect();
    status.setAttribute('data-colour-bar', [r.left, r.top, r.width, r.height].join(','));
  }
  status.setAttribute('data-layers', Object.keys(layers).filter(function (n) { return layers[n].shown; }).join(','));
  if (worst) {
    status.setAttribute('data-worst-face', String(worst.face));
    status.setAttribute('data-worst-planarity', String(worst.planarity));
  }
  status.setAttribute('data-state', 'rendered');
})();
)PVF";
  return text;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_HTML_VIEWER_PAGE_H
