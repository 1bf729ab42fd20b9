// deformseg view: the page's pure parts, which node tests too (test/viewer/viewer_core.test.js):
// decoding the embedded data, the frame lookups of the timeline, the alignment and the graph.
'use strict';

var DeformsegCore = (function () {
  // The bytes of a base64 text.
  function decodeBase64(text) {
    if (typeof atob === 'function') {
      var binary = atob(text);
      var bytes = new Uint8Array(binary.length);
      for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
      return bytes;
    }
    return new Uint8Array(Buffer.from(text, 'base64'));
  }

  // Little-endian 16-bit words of `bytes` (the data are written little-endian whatever the host).
  function uint16s(bytes) {
    var words = new Uint16Array(bytes.length / 2);
    for (var i = 0; i < words.length; ++i) words[i] = bytes[2 * i] | (bytes[2 * i + 1] << 8);
    return words;
  }

  function uint32s(bytes) {
    var words = new Uint32Array(bytes.length / 4);
    for (var i = 0; i < words.length; ++i)
      words[i] = (bytes[4 * i] | (bytes[4 * i + 1] << 8) | (bytes[4 * i + 2] << 16)) + bytes[4 * i + 3] * 16777216;
    return words;
  }

  // Positions quantised to 16 bits in the box [low, high], x y z of each vertex in a row, back
  // to coordinates: q / 65535 of the way from low to high on each axis.
  function dequantize(words, low, high) {
    var out = new Float32Array(words.length);
    for (var i = 0; i < words.length; ++i) {
      var axis = i % 3;
      out[i] = low[axis] + (words[i] / 65535) * (high[axis] - low[axis]);
    }
    return out;
  }

  // The interval of `intervals` (sorted, each {first, last}, covering the frames) holding frame
  // t, by bisection; -1 when none does.
  function intervalAt(intervals, t) {
    var lo = 0, hi = intervals.length - 1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (t < intervals[mid].first) hi = mid - 1;
      else if (t > intervals[mid].last) lo = mid + 1;
      else return mid;
    }
    return -1;
  }

  // The frame of B shown with frame i of A: the first pair of the alignment (pairs [a, b],
  // increasing in both) whose frame of A is i; for a frame the alignment leaves out, that of the
  // nearest pair before it, or the first pair's.
  function alignedFrame(pairs, i) {
    if (pairs.length === 0) return 0;
    var lo = 0, hi = pairs.length - 1, found = 0;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (pairs[mid][0] < i) { found = mid; lo = mid + 1; }
      else hi = mid - 1;
    }
    if (lo < pairs.length && pairs[lo][0] === i) return pairs[lo][1];
    return pairs[found][1];
  }

  // The first frame of A aligned with frame j of B or a later one (a click on B's timeline).
  function firstFrameAlignedWith(pairs, j) {
    for (var k = 0; k < pairs.length; ++k)
      if (pairs[k][1] >= j) return pairs[k][0];
    return pairs.length ? pairs[pairs.length - 1][0] : 0;
  }

  // The layout of a key frame's graph as an arc diagram, so that no two nodes nor labels overlap
  // however many there are: node k at height top + (k + 1/2) spacing in one column, its label to
  // the right; the edge u-v a half ellipse on the left of the column, as wide as a quarter of the
  // rows it spans (at most maxWidth). Gives the nodes' heights, each edge's width and the height
  // the drawing needs.
  function columnLayout(count, edges, spacing, top, maxWidth) {
    var heights = [];
    for (var k = 0; k < count; ++k) heights.push(top + (k + 0.5) * spacing);
    var widths = edges.map(function (e) {
      return Math.min(maxWidth, spacing / 2 + Math.abs(e[1] - e[0]) * spacing / 4);
    });
    return {heights: heights, widths: widths, height: top + count * spacing + spacing / 2};
  }

  // A node's label: R for a rigid node, D and its segment for a deformed one, with its share of
  // the surface in percent (with a decimal under 1 %, where a character's segments often are;
  // "<0.1%" for a share that would round to 0.0 %, since every node covers some of it).
  function nodeLabel(node) {
    var name = node.kind === 'rigid' ? 'R' : 'D' + node.segment, percent = 100 * node.area;
    if (percent < 0.05) return name + ' <0.1%';
    return name + ' ' + (percent < 1 ? percent.toFixed(1) : Math.round(percent)) + '%';
  }

  // "#rrggbb" of [r, g, b] in 0..255.
  function cssColor(rgb) {
    var hex = '#';
    for (var c = 0; c < 3; ++c) hex += (rgb[c] < 16 ? '0' : '') + rgb[c].toString(16);
    return hex;
  }

  // The frame the page opens at: ?frame=N when N is a frame, else 0; and whether it was asked
  // for (then the page opens paused).
  function requestedFrame(search, frames) {
    var match = /[?&]frame=(\d+)/.exec(search || '');
    if (!match) return {frame: 0, given: false};
    return {frame: Math.min(parseInt(match[1], 10), frames - 1), given: true};
  }

  return {
    decodeBase64: decodeBase64, uint16s: uint16s, uint32s: uint32s, dequantize: dequantize,
    intervalAt: intervalAt, alignedFrame: alignedFrame, firstFrameAlignedWith: firstFrameAlignedWith, columnLayout: columnLayout, nodeLabel: nodeLabel,
    cssColor: cssColor, requestedFrame: requestedFrame
  };
})();

if (typeof module !== 'undefined') module.exports = DeformsegCore;
