// ncoffset HTML report: the view (projection of XY / ZX / YZ / isometric, pan and zoom) and
// the axes with their mm scale and grid.
NCO.VIEWS = {
  xy: { name: "XY (G17)", h: "X", v: "Y" },
  zx: { name: "ZX (G18)", h: "Z", v: "X" },
  yz: { name: "YZ (G19)", h: "Y", v: "Z" },
  iso: { name: "isometric", h: "", v: "" },
};
const C30 = Math.cos(Math.PI / 6), S30 = 0.5;

// The view's abscissa and ordinate of a point (mm), as the SVG writer's planes (G17 X right Y
// up, G18 Z right X up, G19 Y right Z up); isometric: seen from +X +Y... towards the origin, Z up.
NCO.project = function (view, x, y, z, out) {
  switch (view) {
    case "zx": out[0] = z; out[1] = x; break;
    case "yz": out[0] = y; out[1] = z; break;
    case "iso": out[0] = (x - y) * C30; out[1] = z + (x + y) * S30; break;
    default: out[0] = x; out[1] = y;
  }
  return out;
};

// The transform mm -> pixels: X = u * k + tx, Y = -v * k + ty.
NCO.T = { k: 1, tx: 0, ty: 0, w: 800, h: 600 };

NCO.size = function () {
  const svg = NCO.svg, r = svg.getBoundingClientRect();
  NCO.T.w = Math.max(50, r.width); NCO.T.h = Math.max(50, r.height);
  svg.setAttribute("viewBox", "0 0 " + NCO.T.w + " " + NCO.T.h);
};

NCO.fit = function () {
  const b = NCO.bbox, view = NCO.state.view, q = [0, 0];
  let u0 = Infinity, v0 = Infinity, u1 = -Infinity, v1 = -Infinity;
  for (let c = 0; c < 8; ++c) {
    NCO.project(view, b[c & 1 ? 3 : 0], b[c & 2 ? 4 : 1], b[c & 4 ? 5 : 2], q);
    u0 = Math.min(u0, q[0]); u1 = Math.max(u1, q[0]); v0 = Math.min(v0, q[1]); v1 = Math.max(v1, q[1]);
  }
  const T = NCO.T, m = 40;
  const k = Math.min((T.w - 2 * m) / Math.max(u1 - u0, 1e-6), (T.h - 2 * m) / Math.max(v1 - v0, 1e-6));
  T.k = Math.min(Math.max(k, 1e-6), 1e7);
  T.tx = T.w / 2 - (u0 + u1) / 2 * T.k;
  T.ty = T.h / 2 + (v0 + v1) / 2 * T.k;
};

// Zooms by `f` about the pixel (px, py).
NCO.zoom = function (f, px, py) {
  const T = NCO.T, k = Math.min(Math.max(T.k * f, 1e-6), 1e7);
  f = k / T.k;
  T.tx = px - (px - T.tx) * f; T.ty = py - (py - T.ty) * f; T.k = k;
  NCO.redraw();
};

NCO.pan = function (dx, dy) { NCO.T.tx += dx; NCO.T.ty += dy; NCO.redraw(); };

// The grid step: 1, 2 or 5 times a power of ten, about 80 pixels apart.
NCO.gridStep = function () {
  const raw = 80 / NCO.T.k, e = Math.pow(10, Math.floor(Math.log10(raw)));
  const m = raw / e;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e;
};

NCO.num = function (v) { return String(+v.toPrecision(10)); };

// Grid lines and their mm labels (2D views), the axis names, a scale bar and the origin of
// the coordinates drawn (WCS with --coords wcs, machine zero with mcs).
NCO.drawAxes = function (g) {
  const T = NCO.T, view = NCO.state.view, V = NCO.VIEWS[view];
  const step = NCO.gridStep();
  let s = "";
  if (view !== "iso") {
    const u0 = (0 - T.tx) / T.k, u1 = (T.w - T.tx) / T.k;
    const v0 = (T.ty - T.h) / T.k, v1 = T.ty / T.k;
    for (let u = Math.ceil(u0 / step) * step; u <= u1; u += step) {
      const X = u * T.k + T.tx;
      s += '<line class="grid" x1="' + X + '" y1="0" x2="' + X + '" y2="' + T.h + '"/>';
      s += '<text x="' + (X + 2) + '" y="' + (T.h - 4) + '">' + NCO.num(u) + "</text>";
    }
    for (let v = Math.ceil(v0 / step) * step; v <= v1; v += step) {
      const Y = -v * T.k + T.ty;
      s += '<line class="grid" x1="0" y1="' + Y + '" x2="' + T.w + '" y2="' + Y + '"/>';
      s += '<text x="2" y="' + (Y - 2) + '">' + NCO.num(v) + "</text>";
    }
    s += '<text x="' + (T.w - 70) + '" y="' + (T.h - 18) + '" style="font-weight:bold">' + V.h + " mm \u2192</text>";
    s += '<text x="6" y="14" style="font-weight:bold">\u2191 ' + V.v + " mm</text>";
  } else {
    const q = [0, 0], ox = 50, oy = T.h - 50;
    ["X", "Y", "Z"].forEach(function (a, i) {
      NCO.project("iso", i === 0 ? 1 : 0, i === 1 ? 1 : 0, i === 2 ? 1 : 0, q);
      const X = ox + q[0] * 30, Y = oy - q[1] * 30;
      s += '<line class="axis" x1="' + ox + '" y1="' + oy + '" x2="' + X + '" y2="' + Y + '"/>';
      s += '<text x="' + (X + 2) + '" y="' + (Y + 4) + '" style="font-weight:bold">' + a + "</text>";
    });
  }
  // The scale bar: one grid step.
  const L = step * T.k, bx = T.w - L - 20, by = T.h - 30;
  s += '<path class="scale" d="M' + bx + " " + (by - 4) + "v4h" + L + "v-4" + '"/>';
  s += '<text x="' + bx + '" y="' + (by - 7) + '">' + NCO.num(step) + " mm</text>";
  // The origin of the coordinates drawn.
  const o = NCO.project(view, 0, 0, 0, [0, 0]), OX = o[0] * T.k + T.tx, OY = -o[1] * T.k + T.ty;
  s += '<g class="origin"><circle cx="' + OX + '" cy="' + OY + '" r="6"/><path d="M' + (OX - 10) +
       " " + OY + "h20M" + OX + " " + (OY - 10) + 'v20"/></g>';
  s += '<text x="' + (OX + 8) + '" y="' + (OY + 14) + '">' +
       (NCO.data.coords === "wcs" ? "WCS origin" : "MCS origin") + "</text>";
  // In MCS: the WCS origin of the frame in force at the selected block (or at the start).
  if (NCO.data.coords !== "wcs") {
    const at = NCO.state.sel && NCO.state.sel.focus >= 0 ? NCO.state.sel.focus : 0;
    let w = [0, 0, 0];
    for (const f of NCO.data.frames || []) if (f[0] <= at) w = [f[1], f[2], f[3]];
    const p = NCO.project(view, w[0], w[1], w[2], [0, 0]);
    const WX = p[0] * T.k + T.tx, WY = -p[1] * T.k + T.ty;
    s += '<g class="origin wcs"><rect x="' + (WX - 5) + '" y="' + (WY - 5) + '" width="10" height="10"/></g>';
    s += '<text x="' + (WX + 8) + '" y="' + (WY - 6) + '">WCS origin</text>';
  }
  g.innerHTML = s;
};
