// The viewer page's pure parts (tools/deformseg/viewer/viewer_core.js) under Node.js:
//   node viewer_core.test.js PATH/TO/viewer_core.js
'use strict';
const assert = require('assert');
const core = require(process.argv[2]);

// base64 of bytes the C++ side wrote, as little-endian words.
assert.deepStrictEqual(Array.from(core.decodeBase64('AAEC/w==')), [0, 1, 2, 255]);
assert.deepStrictEqual(Array.from(core.uint16s(core.decodeBase64('AQD//w=='))), [1, 65535]);
assert.deepStrictEqual(Array.from(core.uint32s(core.decodeBase64('AQAAAP////8='))), [1, 4294967295]);

// Quantised positions back in their box: 0 at low, 65535 at high, each axis its own.
const xyz = core.dequantize(new Uint16Array([0, 65535, 32768]), [-1, 0, 10], [1, 2, 20]);
assert.ok(Math.abs(xyz[0] + 1) < 1e-6 && Math.abs(xyz[1] - 2) < 1e-6 && Math.abs(xyz[2] - 15.0001) < 1e-3);

// The segment or key frame of a frame, by bisection, against a scan of every interval.
const intervals = [{first: 0, last: 4}, {first: 5, last: 5}, {first: 6, last: 19}];
for (let t = 0; t < 20; ++t) {
  const scanned = intervals.findIndex((s) => s.first <= t && t <= s.last);
  assert.strictEqual(core.intervalAt(intervals, t), scanned, 'frame ' + t);
}
assert.strictEqual(core.intervalAt(intervals, 25), -1);

// The frame of B shown with frame i of A: the first pair of i; a frame left out takes the pair
// before it; against a scan.
const pairs = [[0, 0], [0, 1], [1, 2], [3, 3], [3, 4], [4, 6]];
const scan = (i) => {
  const first = pairs.find((p) => p[0] === i);
  if (first) return first[1];
  const before = pairs.filter((p) => p[0] < i);
  return before.length ? before[before.length - 1][1] : pairs[0][1];
};
for (let i = 0; i <= 5; ++i) assert.strictEqual(core.alignedFrame(pairs, i), scan(i), 'frame ' + i + ' of A');
assert.strictEqual(core.alignedFrame([], 3), 0);
assert.strictEqual(core.firstFrameAlignedWith(pairs, 5), 4);
assert.strictEqual(core.firstFrameAlignedWith(pairs, 9), 4);

// Labels, colours, the layout and ?frame=N.
assert.strictEqual(core.nodeLabel({kind: 'rigid', segment: null, area: 0.754}), 'R 75%');
assert.strictEqual(core.nodeLabel({kind: 'deformed', segment: 3, area: 0.25}), 'D3 25%');
assert.strictEqual(core.nodeLabel({kind: 'deformed', segment: 0, area: 0.0034}), 'D0 0.3%');
assert.strictEqual(core.nodeLabel({kind: 'deformed', segment: 7, area: 0.0004}), 'D7 <0.1%');
assert.strictEqual(core.nodeLabel({kind: 'rigid', segment: null, area: 0.0005}), 'R 0.1%');
assert.strictEqual(core.cssColor([255, 8, 160]), '#ff08a0');
// The arc diagram: nodes a spacing apart whatever their count, every arc within its width bound
// and reaching further the more rows it spans, the drawing as tall as its last node and half a row.
for (const count of [1, 2, 5, 15, 64, 200]) {
  const edges = [];
  for (let u = 0; u + 1 < count; ++u) edges.push([u, u + 1], [0, count - 1 - u]);
  const at = core.columnLayout(count, edges, 24, 20, 100);
  assert.strictEqual(at.heights.length, count);
  at.heights.forEach((y, k) => assert.strictEqual(y, 20 + 12 + 24 * k));
  assert.strictEqual(at.height, at.heights[count - 1] + 24);
  edges.forEach((e, i) => {
    assert.ok(at.widths[i] > 0 && at.widths[i] <= 100, 'edge ' + e);
    const longer = edges.findIndex((f) => Math.abs(f[1] - f[0]) > Math.abs(e[1] - e[0]));
    if (longer >= 0) assert.ok(at.widths[longer] >= at.widths[i]);
  });
}
assert.deepStrictEqual(core.requestedFrame('?frame=7', 10), {frame: 7, given: true});
assert.deepStrictEqual(core.requestedFrame('?frame=70', 10), {frame: 9, given: true});
assert.deepStrictEqual(core.requestedFrame('', 10), {frame: 0, given: false});
console.log('viewer_core: all checks passed');
