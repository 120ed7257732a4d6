// ncoffset HTML report: the drawing. Where few segments are in view (NCO.EXACT) each is an
// element of its own (class "seg", data-i, data-line, data-file) drawn exactly (arcs as chords
// of at most a pixel's error); with more, consecutive segments of one style share a decimated
// polyline (class "dec": a point only where it moves the line by a pixel), so a program of
// millions of blocks draws in milliseconds and zooming in gives the exact path again.
NCO.EXACT = 3000;
NCO.PALETTE = ["#1565c0", "#2e7d32", "#ef6c00", "#6a1b9a", "#c62828", "#00838f", "#5d4037",
               "#ad1457", "#827717", "#283593"];
NCO.ZCOLORS = ["#0d47a1", "#1976d2", "#26a69a", "#9ccc65", "#fdd835", "#fb8c00", "#e53935", "#880e4f"];

// The style of output segment i: its class and, colouring by Z or tool, its stroke. One object
// per style (the decimated drawing asks for every segment).
NCO.STYLES = new Map();
NCO.style = function (key, cls, stroke) {
  let s = NCO.STYLES.get(key);
  if (!s) { s = { key: key, cls: cls, stroke: stroke, id: NCO.STYLES.size + 1 }; NCO.STYLES.set(key, s); }
  return s;
};
NCO.styleOf = function (p, i, programmed) {
  if (programmed) return NCO.style(-1, "pseg", "");
  const c = NCO.inserted[i] === 1 ? 2 : NCO.hasFeed(p, i) ? 0 : 1, cls = NCO.CLS[c];
  const mode = NCO.state.colour;
  if (mode === "z") {
    const b = NCO.bbox, f = (p.z[i] - b[2]) / Math.max(b[5] - b[2], 1e-9);
    const k = Math.min(7, Math.max(0, Math.floor(f * 8)));
    return NCO.style(1000 + c * 8 + k, cls, NCO.ZCOLORS[k]);
  }
  if (mode === "tool") {
    const t = p.tool[i];
    return NCO.style(100000 + c * 10000 + t, cls, t < 0 ? "#9e9e9e" : NCO.PALETTE[t % 10]);
  }
  return NCO.style(c, cls, "");
};
NCO.CLS = ["cut", "g0", "ins"];
// A pixel coordinate with one decimal (faster than toFixed).
NCO.px = function (v) { return Math.round(v * 10) / 10; };

NCO.screen = function (x, y, z, q) {
  NCO.project(NCO.state.view, x, y, z, q);
  q[0] = q[0] * NCO.T.k + NCO.T.tx; q[1] = -q[1] * NCO.T.k + NCO.T.ty;
  return q;
};

// Screen points of segment i (start first): a line's two ends, an arc's chords.
NCO.segPoints = function (p, i, exact) {
  const q = [0, 0], pts = [];
  NCO.screen(p.sx[i], p.sy[i], p.sz[i], q); pts.push(q[0], q[1]);
  if (p.arc[i] >= 0) {
    const k = p.arc[i] * 7, r = Math.hypot(p.sx[i] - p.arcs[k], p.sy[i] - p.arcs[k + 1],
                                            p.sz[i] - p.arcs[k + 2]) * NCO.T.k;
    // A chord of angle a deviates r (1 - cos(a/2)) from the arc: at most 0.3 px (exact).
    const step = exact ? Math.max(0.01, 2 * Math.acos(Math.max(-1, 1 - 0.3 / Math.max(r, 0.3))))
                       : Math.max(0.2, 2 * Math.acos(Math.max(-1, 1 - 1.5 / Math.max(r, 1.5))));
    const a = NCO.arcPoints(p, i, step);
    for (let j = 0; j < a.length; j += 3) { NCO.screen(a[j], a[j + 1], a[j + 2], q); pts.push(q[0], q[1]); }
  } else {
    NCO.screen(p.x[i], p.y[i], p.z[i], q); pts.push(q[0], q[1]);
  }
  return pts;
};

NCO.pathD = function (pts) {
  let d = "M" + NCO.px(pts[0]) + " " + NCO.px(pts[1]);
  for (let j = 2; j < pts.length; j += 2) d += "L" + NCO.px(pts[j]) + " " + NCO.px(pts[j + 1]);
  return d;
};

// The segments of p in view (their screen box meets the drawing), in order. All of them when
// the whole drawing is in view (as after fit: no test per segment).
NCO.visible = function (p) {
  const T = NCO.T, q = [0, 0], r = [0, 0], vis = new Int32Array(p.n), b = NCO.bbox;
  let m = 0, inside = true;
  for (let c = 0; c < 8 && inside; ++c) {
    NCO.screen(b[c & 1 ? 3 : 0], b[c & 2 ? 4 : 1], b[c & 4 ? 5 : 2], q);
    inside = q[0] >= 0 && q[0] <= T.w && q[1] >= 0 && q[1] <= T.h;
  }
  if (inside) {
    for (let i = 0; i < p.n; ++i) vis[i] = i;
    return vis;
  }
  for (let i = 0; i < p.n; ++i) {
    NCO.screen(p.x[i], p.y[i], p.z[i], q);
    NCO.screen(p.sx[i], p.sy[i], p.sz[i], r);
    let x0 = Math.min(q[0], r[0]), x1 = Math.max(q[0], r[0]);
    let y0 = Math.min(q[1], r[1]), y1 = Math.max(q[1], r[1]);
    if (p.arc[i] >= 0) {  // the whole circle's box
      const k = p.arc[i] * 7;
      NCO.screen(p.arcs[k], p.arcs[k + 1], p.arcs[k + 2], q);
      const rr = Math.hypot(p.sx[i] - p.arcs[k], p.sy[i] - p.arcs[k + 1], p.sz[i] - p.arcs[k + 2]) * T.k;
      x0 = Math.min(x0, q[0] - rr); x1 = Math.max(x1, q[0] + rr);
      y0 = Math.min(y0, q[1] - rr); y1 = Math.max(y1, q[1] + rr);
    }
    if (x1 >= -2 && x0 <= T.w + 2 && y1 >= -2 && y0 <= T.h + 2) vis[m++] = i;
  }
  return vis.subarray(0, m);
};

NCO.attrs = function (p, i) {
  return ' data-line="' + p.line[i] + '" data-file="' + p.file[i] + '"';
};

// Draws path p into group g: exact elements or decimated polylines.
NCO.drawPath = function (p, g, programmed) {
  const vis = NCO.visible(p);
  if (!programmed) NCO.shown = vis;
  let s = "";
  if (vis.length <= NCO.EXACT) {
    for (let k = 0; k < vis.length; ++k) {
      const i = vis[k], st = NCO.styleOf(p, i, programmed);
      s += '<path class="' + (programmed ? "pseg" : "seg " + st.cls) + '"' + NCO.attrs(p, i) +
           ' data-i="' + i + '"' + (st.stroke ? ' style="stroke:' + st.stroke + '"' : "") +
           ' d="' + NCO.pathD(NCO.segPoints(p, i, true)) + '"/>';
    }
    NCO.svg.dataset.mode = "exact";
  } else {
    s = NCO.decimated(p, vis, programmed);
    NCO.svg.dataset.mode = "decimated";
  }
  g.innerHTML = s;
  return vis.length;
};

// Consecutive segments of one style as one polyline that keeps a point only where it enters a
// 2-pixel cell of the drawing not yet drawn in that style: a dense region (a finishing path of
// rows closer than a pixel) costs as many points as it has cells, not as it has blocks. Where
// points in cells drawn before were left out, the line is broken (M) at the last of them, so
// no line is drawn where the path did not go.
NCO.CELL = 2;
NCO.decimated = function (p, vis, programmed) {
  const T = NCO.T, cw = NCO.CELL, gw = Math.ceil(T.w / cw) + 1, gh = Math.ceil(T.h / cw) + 1;
  if (!NCO.grid || NCO.grid.length !== gw * gh) NCO.grid = new Uint16Array(gw * gh);
  const grid = NCO.grid;
  grid.fill(0);
  let s = "", d = "", st = null, first = -1, last = -1, pts = 0, lc = -1, far = false, fx = 0, fy = 0;
  const q = [0, 0];
  const point = function (x, y) {
    const cx = Math.floor(x / cw), cy = Math.floor(y / cw);
    const c = cx >= 0 && cy >= 0 && cx < gw && cy < gh ? cy * gw + cx : -2;
    if (c === lc) return;  // in the cell of the last point: within 2 px of it
    if (c >= 0 && grid[c] === st.id) { far = true; fx = x; fy = y; return; }
    if (c >= 0) grid[c] = st.id;
    if (far) { d += "M" + NCO.px(fx) + " " + NCO.px(fy); far = false; }
    d += "L" + NCO.px(x) + " " + NCO.px(y); lc = c; ++pts;
  };
  const flush = function () {
    if (first < 0) return;
    NCO.screen(p.x[last], p.y[last], p.z[last], q);
    if (far) d += "M" + NCO.px(fx) + " " + NCO.px(fy);
    d += "L" + NCO.px(q[0]) + " " + NCO.px(q[1]);
    s += '<path class="' + (programmed ? "pseg dec" : "dec " + st.cls) + '"' + NCO.attrs(p, first) +
         ' data-i0="' + first + '" data-i1="' + last + '"' +
         (st.stroke ? ' style="stroke:' + st.stroke + '"' : "") + ' d="' + d + '"/>';
    first = -1; d = ""; pts = 0; far = false; lc = -1;
  };
  for (let k = 0; k < vis.length; ++k) {
    const i = vis[k], sty = NCO.styleOf(p, i, programmed);
    const joined = first >= 0 && last === i - 1 && !(p.kind[i] & 8);
    if (sty !== st || !joined || pts > 4000) {
      flush();
      st = sty; first = i;
      NCO.screen(p.sx[i], p.sy[i], p.sz[i], q);
      d = "M" + NCO.px(q[0]) + " " + NCO.px(q[1]);
      lc = -1; point(q[0], q[1]);
    }
    if (p.arc[i] >= 0) {
      const a = NCO.segPoints(p, i, false);
      for (let j = 2; j < a.length; j += 2) point(a[j], a[j + 1]);
    } else {
      NCO.screen(p.x[i], p.y[i], p.z[i], q);
      point(q[0], q[1]);
    }
    last = i;
  }
  flush();
  return s;
};

// Start, end and direction marks, tool changes, warnings and the alarm.
NCO.drawMarks = function (g) {
  const p = NCO.out, q = [0, 0];
  let s = "";
  if (p.n === 0) { g.innerHTML = ""; return; }
  const vis = NCO.shown, every = Math.max(1, Math.floor(vis.length / 60));
  for (let k = 0; k < vis.length; k += every) {  // direction arrows at segment middles
    const i = vis[k], a = NCO.segPoints(p, i, false), m = (a.length >> 2) << 1;
    const x0 = a[m - 2 >= 0 ? m - 2 : 0], y0 = a[m - 1 >= 0 ? m - 1 : 1];
    const x1 = a[m], y1 = a[m + 1], L = Math.hypot(x1 - x0, y1 - y0);
    if (L < 0.5 || (every === 1 && Math.hypot(a[a.length - 2] - a[0], a[a.length - 1] - a[1]) < 30)) continue;
    const ux = (x1 - x0) / L, uy = (y1 - y0) / L, mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    s += '<path class="arrow' + (NCO.hasFeed(p, i) ? "" : " g0") + '" d="M' + (mx + ux * 5) + " " +
         (my + uy * 5) + "L" + (mx - ux * 4 - uy * 4) + " " + (my - uy * 4 + ux * 4) + "L" +
         (mx - ux * 4 + uy * 4) + " " + (my - uy * 4 - ux * 4) + 'Z"/>';
  }
  NCO.screen(p.sx[0], p.sy[0], p.sz[0], q);
  s += '<circle class="start" cx="' + q[0] + '" cy="' + q[1] + '" r="6"><title>start</title></circle>';
  NCO.screen(p.x[p.n - 1], p.y[p.n - 1], p.z[p.n - 1], q);
  s += '<rect class="end" x="' + (q[0] - 4) + '" y="' + (q[1] - 4) + '" width="8" height="8"><title>end</title></rect>';
  const at = function (i) {  // where the segments before index i end
    if (i <= 0) return NCO.screen(p.sx[0], p.sy[0], p.sz[0], q);
    const j = Math.min(i, p.n) - 1;
    return NCO.screen(p.x[j], p.y[j], p.z[j], q);
  };
  const tools = NCO.data.tools;
  NCO.data.changes.forEach(function (c) {
    const t = tools[c[1]];
    at(c[0]);
    s += '<g><path class="toolmark" d="M' + q[0] + " " + (q[1] - 7) + "l7 7l-7 7l-7 -7Z" + '"/><text x="' +
         (q[0] + 8) + '" y="' + (q[1] - 6) + '">T' + t.t + " D" + t.d + "</text></g>";
  });
  NCO.data.notes.forEach(function (n) {
    if (!n[2]) return;
    at(n[4]);
    s += '<path class="warnmark" data-file="' + n[0] + '" data-line="' + n[1] + '" d="M' + q[0] + " " +
         (q[1] - 9) + "l8 14h-16Z" + '"><title>warning ' + n[2] + ": " + NCO.escape(n[3]) + "</title></path>";
  });
  const al = NCO.data.alarm;
  if (al) {
    at(al[4]);
    s += '<g class="alarmmark-g"><circle class="alarmmark" data-file="' + al[0] + '" data-line="' + al[1] +
         '" cx="' + q[0] + '" cy="' + q[1] + '" r="9"><title>alarm ' + al[2] + ": " + NCO.escape(al[3]) +
         '</title></circle><text x="' + (q[0] + 12) + '" y="' + (q[1] + 4) + '" style="fill:#b00000">alarm ' + al[2] + "</text></g>";
  }
  g.innerHTML = s;
};

// The selected segments over everything, and the tool at the selected block.
NCO.drawSelection = function (g) {
  const sel = NCO.state.sel, p = NCO.out;
  let s = "";
  if (sel) {
    const segs = sel.segs;
    for (let k = 0; k < segs.length && k < 2000; ++k) {
      const i = segs[k];
      s += '<path class="seg selected"' + NCO.attrs(p, i) + ' data-i="' + i + '" d="' +
           NCO.pathD(NCO.segPoints(p, i, true)) + '"/>';
    }
    if (segs.length) s += NCO.toolShape(sel.focus >= 0 ? sel.focus : segs[segs.length - 1]);
  }
  g.innerHTML = s;
};

// The tool at the end of segment i: its tip (the point in WCS; in MCS the point less the length
// vector), a circle of its radius and its body along the length vector.
NCO.toolShape = function (i) {
  const p = NCO.out, slot = p.tool[i], t = slot >= 0 ? NCO.data.tools[slot] : null;
  if (!t) return "";
  const l = t.l, wcs = NCO.data.coords === "wcs";
  const tx = p.x[i] - (wcs ? 0 : l[0]), ty = p.y[i] - (wcs ? 0 : l[1]), tz = p.z[i] - (wcs ? 0 : l[2]);
  const len = Math.hypot(l[0], l[1], l[2]);
  const ax = len > 1e-9 ? l[0] / len : 0, ay = len > 1e-9 ? l[1] / len : 0, az = len > 1e-9 ? l[2] / len : 1;
  const body = Math.max(len, 4 * t.r, 10), q = [0, 0], r = [0, 0], k = NCO.T.k;
  NCO.screen(tx, ty, tz, q);
  NCO.screen(tx + ax * body, ty + ay * body, tz + az * body, r);
  const R = Math.max(t.r * k, 2);
  let s = '<g class="toolg"><title>T' + t.t + " D" + t.d + " R" + NCO.num(t.r) + '</title><circle class="tool" cx="' +
          q[0] + '" cy="' + q[1] + '" r="' + R + '"/>';
  const dx = r[0] - q[0], dy = r[1] - q[1], L = Math.hypot(dx, dy);
  if (L > R * 0.5) {
    const nx = -dy / L * R, ny = dx / L * R;
    s += '<path class="tool" d="M' + (q[0] + nx) + " " + (q[1] + ny) + "L" + (r[0] + nx) + " " + (r[1] + ny) +
         "L" + (r[0] - nx) + " " + (r[1] - ny) + "L" + (q[0] - nx) + " " + (q[1] - ny) + 'Z"/>';
  }
  return s + "</g>";
};

// The output segment nearest to pixel (px, py) among those in view, within `within` pixels.
NCO.nearest = function (px, py, within) {
  const p = NCO.out, vis = NCO.shown || [];
  let best = -1, bd = within;
  for (let k = 0; k < vis.length; ++k) {
    const i = vis[k], a = NCO.segPoints(p, i, false);
    for (let j = 2; j < a.length; j += 2) {
      const x0 = a[j - 2], y0 = a[j - 1], dx = a[j] - x0, dy = a[j + 1] - y0;
      const L2 = dx * dx + dy * dy, t = L2 > 0 ? Math.max(0, Math.min(1, ((px - x0) * dx + (py - y0) * dy) / L2)) : 0;
      const d = Math.hypot(px - x0 - t * dx, py - y0 - t * dy);
      if (d < bd) { bd = d; best = i; }
    }
  }
  return best;
};
