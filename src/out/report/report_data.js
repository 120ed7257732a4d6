"use strict";
// ncoffset HTML report: the path data (docs/output-formats.md "HTML"). The page's JSON holds
// each path (output and programmed) as columns; here they become typed arrays, with the start
// point of every segment, its feed, file and tool, and the arcs' geometry.
const NCO = { state: {} };

NCO.MOTION = ["G0", "G1", "G2", "G3"];
NCO.THREAD = ["G33", "G34", "G35", "G331", "G332", "G63"];
NCO.UNIT = ["mm/min", "mm/rev", "1/min"];

NCO.decodePath = function (c) {
  const n = c.X.length;
  const p = {
    n: n,
    x: new Float64Array(c.X), y: new Float64Array(c.Y), z: new Float64Array(c.Z),
    sx: new Float64Array(n), sy: new Float64Array(n), sz: new Float64Array(n),
    kind: new Uint16Array(c.K), line: new Int32Array(n), file: new Int32Array(n),
    tool: new Int32Array(n), feed: new Float64Array(n), unit: new Uint8Array(n),
    arc: new Int32Array(n).fill(-1), arcs: new Float64Array(c.A.length * 7),
  };
  let l = 0;
  for (let i = 0; i < n; ++i) { l += c.L[i]; p.line[i] = l; }
  for (let i = 1; i < n; ++i) { p.sx[i] = p.x[i - 1]; p.sy[i] = p.y[i - 1]; p.sz[i] = p.z[i - 1]; }
  for (const s of c.S) { p.sx[s[0]] = s[1]; p.sy[s[0]] = s[2]; p.sz[s[0]] = s[3]; }
  const runs = c.R;
  for (let r = 0; r < runs.length; ++r) {
    const [from, file, tool, feed, unit] = runs[r];
    const to = r + 1 < runs.length ? runs[r + 1][0] : n;
    p.file.fill(file, from, to); p.tool.fill(tool, from, to);
    p.feed.fill(feed, from, to); p.unit.fill(unit, from, to);
  }
  c.A.forEach(function (a, k) {
    p.arc[a[0]] = k;
    for (let j = 0; j < 7; ++j) p.arcs[k * 7 + j] = a[j + 1];
  });
  return p;
};

NCO.motion = function (p, i) { return p.kind[i] & 3; };
// The motion's name: a thread or tapping line is drawn as G1 but named as programmed.
NCO.motionName = function (p, i) {
  return p.kind[i] & 32 ? NCO.THREAD[(p.kind[i] >> 6) & 7] : NCO.MOTION[p.kind[i] & 3];
};
NCO.hasFeed = function (p, i) { return (p.kind[i] & 4) !== 0; };
NCO.isArc = function (p, i) { return (p.kind[i] & 2) !== 0; };

// An arc as in src/out/arc_geometry.cpp: centre c, u from c to the start, w = n x u, the sweep
// about n (G3 > 0, G2 < 0, end on start: a full circle, TURN= turns added), the helix rise
// along n and the radius at both ends (a spiral keeps both).
NCO.arcGeometry = function (p, i) {
  const k = p.arc[i] * 7, a = p.arcs;
  const cx = a[k], cy = a[k + 1], cz = a[k + 2], nx = a[k + 3], ny = a[k + 4], nz = a[k + 5];
  const turns = a[k + 6];
  let ux = p.sx[i] - cx, uy = p.sy[i] - cy, uz = p.sz[i] - cz;
  const un = ux * nx + uy * ny + uz * nz;
  ux -= un * nx; uy -= un * ny; uz -= un * nz;
  const r0 = Math.hypot(ux, uy, uz) || 1e-12;
  ux /= r0; uy /= r0; uz /= r0;
  const wx = ny * uz - nz * uy, wy = nz * ux - nx * uz, wz = nx * uy - ny * ux;
  let ex = p.x[i] - cx, ey = p.y[i] - cy, ez = p.z[i] - cz;
  const rise = ex * nx + ey * ny + ez * nz - un;
  const en = ex * nx + ey * ny + ez * nz;
  ex -= en * nx; ey -= en * ny; ez -= en * nz;
  const r1 = Math.hypot(ex, ey, ez);
  let ang = Math.atan2(ex * wx + ey * wy + ez * wz, ex * ux + ey * uy + ez * uz);
  const ccw = NCO.motion(p, i) === 3;
  if (ccw) { if (ang <= 1e-9) ang += 2 * Math.PI; } else { if (ang >= -1e-9) ang -= 2 * Math.PI; }
  const sweep = ang + (ccw ? 1 : -1) * 2 * Math.PI * turns;
  return { cx: cx + un * nx, cy: cy + un * ny, cz: cz + un * nz, ux, uy, uz, wx, wy, wz,
           nx, ny, nz, r0, r1, sweep, rise };
};

// Points along segment i (start excluded, end included) with chords of at most `step` radians.
NCO.arcPoints = function (p, i, step) {
  const g = NCO.arcGeometry(p, i);
  const m = Math.max(2, Math.min(720, Math.ceil(Math.abs(g.sweep) / step)));
  const out = new Float64Array(m * 3);
  for (let j = 1; j <= m; ++j) {
    const t = j / m, ang = t * g.sweep, r = g.r0 + (g.r1 - g.r0) * t;
    const c = Math.cos(ang) * r, s = Math.sin(ang) * r, h = t * g.rise;
    out[(j - 1) * 3] = g.cx + c * g.ux + s * g.wx + h * g.nx;
    out[(j - 1) * 3 + 1] = g.cy + c * g.uy + s * g.wy + h * g.ny;
    out[(j - 1) * 3 + 2] = g.cz + c * g.uz + s * g.wz + h * g.nz;
  }
  out[(m - 1) * 3] = p.x[i]; out[(m - 1) * 3 + 1] = p.y[i]; out[(m - 1) * 3 + 2] = p.z[i];
  return out;
};

// The bounding box of a path (arcs with their whole circle: a box a little large is harmless).
NCO.box = function (p, box) {
  for (let i = 0; i < p.n; ++i) {
    NCO.addPoint(box, p.x[i], p.y[i], p.z[i]);
    if (p.kind[i] & 8) NCO.addPoint(box, p.sx[i], p.sy[i], p.sz[i]);
    if (p.arc[i] >= 0) {
      const k = p.arc[i] * 7, r = Math.hypot(p.sx[i] - p.arcs[k], p.sy[i] - p.arcs[k + 1],
                                              p.sz[i] - p.arcs[k + 2]);
      NCO.addPoint(box, p.arcs[k] - r, p.arcs[k + 1] - r, p.arcs[k + 2] - r);
      NCO.addPoint(box, p.arcs[k] + r, p.arcs[k + 1] + r, p.arcs[k + 2] + r);
    }
  }
  return box;
};
NCO.addPoint = function (b, x, y, z) {
  if (x < b[0]) b[0] = x; if (y < b[1]) b[1] = y; if (z < b[2]) b[2] = z;
  if (x > b[3]) b[3] = x; if (y > b[4]) b[4] = y; if (z > b[5]) b[5] = z;
};

// Which programmed segment each output segment comes from (-2: the output segment itself,
// kind + 16; else the same file and line, searched forward from the last match: both paths run
// in program order), and which output elements compensation inserted: a circle where the
// programmed block is a line (the corner circle of G450, the circles of smooth approach), or an
// element without a programmed block of its line.
NCO.matchProgrammed = function (out, prog) {
  const match = new Int32Array(out.n).fill(-1), inserted = new Uint8Array(out.n);
  let j = 0;
  for (let i = 0; i < out.n; ++i) {
    if (out.kind[i] & 16) { match[i] = -2; continue; }
    const f = out.file[i], l = out.line[i];
    let found = -1;
    for (let k = j; k < prog.n && k < j + 64; ++k)
      if (prog.line[k] === l && prog.file[k] === f) { found = k; break; }
    if (found < 0)
      for (let k = j - 1; k >= 0 && k > j - 16; --k)
        if (prog.line[k] === l && prog.file[k] === f) { found = k; break; }
    if (found >= 0) {
      match[i] = found; j = found;
      if (NCO.isArc(out, i) && !NCO.isArc(prog, found)) inserted[i] = 1;
    } else {
      inserted[i] = 1;
    }
  }
  return { match, inserted };
};

// The segments of one block (file, line) of the output path.
NCO.segmentsOf = function (p, file, line) {
  const r = [];
  for (let i = 0; i < p.n; ++i) if (p.line[i] === line && p.file[i] === file) r.push(i);
  return r;
};

NCO.fmt = function (v) {
  const d = NCO.data.decimals;
  if (d >= 0) return String(+v.toFixed(d));
  return String(+v.toPrecision(12));
};

NCO.escape = function (s) {
  return s.replace(/[&<>"]/g, function (c) {
    return c === "&" ? "&amp;" : c === "<" ? "&lt;" : c === ">" ? "&gt;" : "&quot;";
  });
};

NCO.load = function () {
  const el = document.getElementById("nco-data");
  const t0 = performance.now();
  const d = JSON.parse(el.textContent);
  el.textContent = "";  // the text is not needed twice
  NCO.data = d;
  NCO.times = { parse: Math.round(performance.now() - t0) };
  NCO.out = NCO.decodePath(d.out);
  NCO.prog = NCO.decodePath(d.prog);
  if (d.skip_first) {  // assumed start position (no --start): the first move is not drawn
    for (const p of [NCO.out, NCO.prog])
      if (p.n > 0) { p.sx[0] = p.x[0]; p.sy[0] = p.y[0]; p.sz[0] = p.z[0]; }
  }
  d.out = d.prog = null;
  const m = NCO.matchProgrammed(NCO.out, NCO.prog);
  NCO.match = m.match; NCO.inserted = m.inserted;
  const box = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  NCO.box(NCO.out, box); NCO.box(NCO.prog, box);
  if (!(box[0] <= box[3])) box.splice(0, 6, -1, -1, -1, 1, 1, 1);
  NCO.bbox = box;
  NCO.times.decode = Math.round(performance.now() - t0) - NCO.times.parse;
  NCO.lines = [];  // the program text of each file, split on first use
};

// The lines of file f: an index of where each starts, made on first use (a million lines in
// tens of milliseconds; no array of a million strings).
NCO.fileLines = function (f) {
  if (!NCO.lines[f]) {
    const text = NCO.data.src[f] === undefined ? "" : NCO.data.src[f];
    const starts = [0];
    for (let at = text.indexOf("\n"); at >= 0; at = text.indexOf("\n", at + 1)) starts.push(at + 1);
    if (starts[starts.length - 1] === text.length) starts.pop();
    NCO.lines[f] = { text: text, starts: starts, length: starts.length };
  }
  return NCO.lines[f];
};

// Line i (0-based) of file f, without its end.
NCO.lineText = function (f, i) {
  const l = NCO.fileLines(f);
  if (i < 0 || i >= l.length) return "";
  const end = i + 1 < l.length ? l.starts[i + 1] - 1 : l.text.length;
  return l.text.slice(l.starts[i], end).replace(/\r$/, "");
};
