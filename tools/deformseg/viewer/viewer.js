// deformseg view: plays the animations of data.js (window.DEFORMSEG_VIEW) with three.js, each
// coloured as the tool computed, with its timeline of temporal segments and key frames, the
// current key frame's graph and, for two animations, their alignment.
'use strict';

(function () {
  var core = DeformsegCore;
  var status = document.getElementById('status');

  function fail(message) {
    status.textContent = 'error: ' + message;
    status.dataset.state = 'error';
  }
  window.addEventListener('error', function (event) { fail(event.message); });

  // ---- One animation: its mesh in a view of its own, its timeline and its graph ----------------

  function Animation(spec, container) {
    this.spec = spec;
    this.frames = spec.frames;
    this.vertices = spec.vertices;
    this.positions = core.dequantize(core.uint16s(core.decodeBase64(spec.positions)), spec.box.low, spec.box.high);
    this.triangles = core.uint32s(core.decodeBase64(spec.triangle_corners));
    var indexBytes = core.decodeBase64(spec.color.indices);
    this.colorIndices = spec.color.index_bytes === 2 ? core.uint16s(indexBytes) : indexBytes;
    this.palette = spec.color.palette.map(function (rgb) { return [rgb[0] / 255, rgb[1] / 255, rgb[2] / 255]; });
    this.buildPanel(container);
    this.buildScene();
  }

  Animation.prototype.buildPanel = function (container) {
    var panel = document.createElement('div');
    panel.className = 'view';
    var heading = document.createElement('h2');
    heading.textContent = this.spec.name + ' (' + this.frames + ' frames, ' + this.spec.triangles + ' triangles)';
    panel.appendChild(heading);
    var row = document.createElement('div');
    row.className = 'row';
    this.canvas = document.createElement('canvas');
    this.canvas.width = 420;
    this.canvas.height = 360;
    row.appendChild(this.canvas);
    this.graph = document.createElement('canvas');
    this.graph.width = 240;
    this.graph.height = 220;
    row.appendChild(this.graph);
    panel.appendChild(row);
    this.timeline = document.createElement('canvas');
    this.timeline.className = 'timeline';
    this.timeline.width = 628;
    this.timeline.height = 36;
    panel.appendChild(this.timeline);
    panel.appendChild(legendOf(this.spec.color));
    container.appendChild(panel);
  };

  // The camera looks along the axis in which the whole motion's box is thinnest, as the tool's
  // pictures do; up is +y, or +z when the view is along y.
  Animation.prototype.buildScene = function () {
    var box = this.spec.box;
    var size = [0, 1, 2].map(function (a) { return box.high[a] - box.low[a]; });
    var centre = new THREE.Vector3((box.low[0] + box.high[0]) / 2, (box.low[1] + box.high[1]) / 2,
                                   (box.low[2] + box.high[2]) / 2);
    var thinnest = size.indexOf(Math.min.apply(null, size));
    var radius = Math.max(0.5 * Math.hypot(size[0], size[1], size[2]), 1e-9);
    this.renderer = new THREE.WebGLRenderer({canvas: this.canvas, antialias: true, preserveDrawingBuffer: true});
    this.renderer.setClearColor(0xffffff);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, this.canvas.width / this.canvas.height, radius / 100, radius * 100);
    var toward = new THREE.Vector3(0, 0, 0).setComponent(thinnest, 1);
    this.camera.up.set(0, thinnest === 1 ? 0 : 1, thinnest === 1 ? 1 : 0);
    this.camera.position.copy(centre).addScaledVector(toward, radius / Math.tan(THREE.Math.degToRad(17.5)));
    this.camera.lookAt(centre);
    this.controls = new THREE.OrbitControls(this.camera, this.canvas);
    this.controls.target.copy(centre);
    this.controls.update();
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 0.65));
    var light = new THREE.DirectionalLight(0xffffff, 0.45);
    light.position.copy(this.camera.position);
    this.scene.add(light);
    var corners = this.spec.triangles * 3;
    this.geometry = new THREE.BufferGeometry();
    this.geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(corners * 3), 3));
    this.geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(corners * 3), 3));
    var material = new THREE.MeshLambertMaterial({vertexColors: THREE.VertexColors, side: THREE.DoubleSide});
    this.scene.add(new THREE.Mesh(this.geometry, material));
    var self = this;
    this.controls.addEventListener('change', function () { self.render(); });
  };

  // Frame t's positions and colours, corner by corner (every triangle flat in its own colour).
  Animation.prototype.show = function (t) {
    this.current = t;
    var position = this.geometry.attributes.position.array, color = this.geometry.attributes.color.array;
    var base = t * this.vertices * 3, faces = this.spec.triangles;
    for (var f = 0; f < faces; ++f) {
      var rgb = this.palette[this.colorIndices[t * faces + f]];
      for (var c = 0; c < 3; ++c) {
        var v = this.triangles[3 * f + c], at = 9 * f + 3 * c;
        position[at] = this.positions[base + 3 * v];
        position[at + 1] = this.positions[base + 3 * v + 1];
        position[at + 2] = this.positions[base + 3 * v + 2];
        color[at] = rgb[0];
        color[at + 1] = rgb[1];
        color[at + 2] = rgb[2];
      }
    }
    this.geometry.attributes.position.needsUpdate = true;
    this.geometry.attributes.color.needsUpdate = true;
    this.geometry.computeVertexNormals();
    this.geometry.computeBoundingSphere();
    this.render();
    this.drawTimeline();
    this.drawGraph();
  };

  Animation.prototype.render = function () { this.renderer.render(this.scene, this.camera); };

  // The temporal segments as coloured bands, the key frames as ticks, the current frame marked.
  Animation.prototype.drawTimeline = function () {
    var g = this.timeline.getContext('2d'), w = this.timeline.width, frames = this.frames;
    var x = function (t) { return (t / frames) * w; };
    g.clearRect(0, 0, w, this.timeline.height);
    this.spec.segments.forEach(function (s, k) {
      g.fillStyle = k % 2 ? '#9ecae1' : '#3182bd';
      g.fillRect(x(s.first), 0, x(s.last + 1) - x(s.first), 16);
    });
    g.fillStyle = '#222';
    this.spec.key_frames.forEach(function (k) { g.fillRect(x(k.first), 18, 1, 10); });
    g.fillStyle = '#d62728';
    g.fillRect(x(this.current), 0, Math.max(2, w / frames), 36);
  };

  // The current key frame's graph as an arc diagram (core.columnLayout): nodes in a column,
  // coloured as on the mesh, labelled on their right, edges as arcs on their left. The canvas
  // grows with the nodes.
  Animation.prototype.drawGraph = function () {
    var k = core.intervalAt(this.spec.key_frames, this.current);
    var key = k < 0 ? {nodes: [], edges: []} : this.spec.key_frames[k];
    var x = 130, radius = 8;
    var at = core.columnLayout(key.nodes.length, key.edges, 24, 24, x - radius - 6);
    if (this.graph.height !== Math.max(220, at.height)) this.graph.height = Math.max(220, at.height);
    var g = this.graph.getContext('2d');
    g.clearRect(0, 0, this.graph.width, this.graph.height);
    if (k < 0) return;
    g.fillStyle = '#222';
    g.font = '13px sans-serif';
    g.fillText('key frame ' + k + ': frames ' + key.first + '-' + key.last, 4, 15);
    g.strokeStyle = '#555';
    key.edges.forEach(function (e, i) {
      var top = Math.min(at.heights[e[0]], at.heights[e[1]]), bottom = Math.max(at.heights[e[0]], at.heights[e[1]]);
      g.beginPath();
      g.ellipse(x, (top + bottom) / 2, at.widths[i], (bottom - top) / 2, 0, Math.PI / 2, 3 * Math.PI / 2);
      g.stroke();
    });
    key.nodes.forEach(function (node, n) {
      g.fillStyle = core.cssColor(node.color);
      g.beginPath();
      g.arc(x, at.heights[n], radius, 0, 2 * Math.PI);
      g.fill();
      g.stroke();
      g.fillStyle = '#222';
      g.fillText(core.nodeLabel(node), x + radius + 6, at.heights[n] + 4);
    });
  };

  // The legend of a colouring: a scale with its values, or one swatch per item.
  function legendOf(color) {
    var legend = document.createElement('div');
    legend.className = 'legend';
    legend.appendChild(document.createTextNode(color.legend.title + ':'));
    if (color.legend.kind === 'scale') {
      var bar = document.createElement('canvas');
      bar.width = 200;
      bar.height = 12;
      var g = bar.getContext('2d');
      for (var x = 0; x < bar.width; ++x) {
        g.fillStyle = core.cssColor(color.palette[Math.round((x / (bar.width - 1)) * (color.palette.length - 1))]);
        g.fillRect(x, 0, 1, 12);
      }
      legend.appendChild(document.createTextNode(' ' + color.legend.low + ' '));
      legend.appendChild(bar);
      legend.appendChild(document.createTextNode(' ' + color.legend.high));
      return legend;
    }
    color.legend.items.forEach(function (item) {
      var swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = core.cssColor(color.palette[item.color]);
      legend.appendChild(swatch);
      legend.appendChild(document.createTextNode(item.name));
    });
    return legend;
  }

  // ---- The page: controls, playing, the alignment of two animations ---------------------------

  function drawAlignment(canvas, alignment, framesA, framesB, i, j) {
    var g = canvas.getContext('2d'), w = canvas.width, h = canvas.height;
    g.fillStyle = '#f4f4f4';
    g.fillRect(0, 0, w, h);
    g.fillStyle = '#d62728';
    var cw = w / framesB, ch = h / framesA;
    alignment.pairs.forEach(function (p) { g.fillRect(p[1] * cw, p[0] * ch, Math.max(1, cw), Math.max(1, ch)); });
    g.strokeStyle = '#222';
    g.strokeRect(j * cw - 3, i * ch - 3, cw + 6, ch + 6);
  }

  function start() {
    var data = window.DEFORMSEG_VIEW;
    if (!data) throw new Error('data.js did not load');
    document.getElementById('title').textContent = data.title;
    document.title = data.title;
    var container = document.getElementById('views');
    var animations = data.animations.map(function (spec) { return new Animation(spec, container); });
    var a = animations[0], b = animations[1];
    var slider = document.getElementById('slider'), label = document.getElementById('frame');
    var playButton = document.getElementById('play'), speed = document.getElementById('speed');
    var alignmentPanel = document.getElementById('alignment-panel');
    var alignmentCanvas = document.getElementById('alignment');
    slider.max = a.frames - 1;
    if (b) {
      alignmentPanel.style.display = 'block';
      container.appendChild(alignmentPanel);
      document.getElementById('similarity').textContent =
          'similarity ' + data.alignment.value.toFixed(3) + ' (' + data.alignment.policy + ')';
    }

    function seek(t) {
      t = Math.max(0, Math.min(a.frames - 1, t));
      a.show(t);
      slider.value = t;
      var text = 'frame ' + a.spec.frame_numbers[t];
      if (b) {
        var j = core.alignedFrame(data.alignment.pairs, t);
        b.show(j);
        text += ' with frame ' + b.spec.frame_numbers[j] + ' of B';
        drawAlignment(alignmentCanvas, data.alignment, a.frames, b.frames, t, j);
      }
      label.textContent = text;
      status.textContent = 'ready: ' + text;
      if (status.dataset.state !== 'ready') status.dataset.readyMs = Math.round(performance.now());
      status.dataset.state = 'ready';
      status.dataset.frame = t;
    }

    var playing = false, position = 0, last = 0;
    function step(now) {
      if (!playing) return;
      position = (position + ((now - last) / 1000) * data.fps * parseFloat(speed.value)) % a.frames;
      last = now;
      if (Math.floor(position) !== a.current) seek(Math.floor(position));
      requestAnimationFrame(step);
    }
    function play(on) {
      playing = on;
      playButton.textContent = on ? 'Pause' : 'Play';
      if (on) {
        position = a.current;
        last = performance.now();
        requestAnimationFrame(step);
      }
    }
    playButton.addEventListener('click', function () { play(!playing); });
    slider.addEventListener('input', function () { play(false); seek(parseInt(slider.value, 10)); });
    animations.forEach(function (animation) {
      animation.timeline.addEventListener('click', function (event) {
        var rect = animation.timeline.getBoundingClientRect();
        var t = Math.floor(((event.clientX - rect.left) / rect.width) * animation.frames);
        play(false);
        seek(animation === a ? t : core.firstFrameAlignedWith(data.alignment.pairs, t));
      });
    });

    var asked = core.requestedFrame(window.location.search, a.frames);
    seek(asked.frame);
    if (!asked.given) play(true);
  }

  try {
    start();
  } catch (error) {
    fail(error.message);
  }
})();
