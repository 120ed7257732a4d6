// ncoffset HTML report: the toolbar, selection (segment <-> program line, both ways), hover,
// keyboard (next / previous block) and the start.
NCO.redraw = function () {
  if (NCO.frame) return;
  NCO.frame = requestAnimationFrame(function () { NCO.frame = 0; NCO.drawNow(); });
};

NCO.drawNow = function () {
  const T = NCO.T, svg = NCO.svg;
  NCO.drawAxes(NCO.g.axes);
  if (NCO.state.programmed) NCO.drawPath(NCO.prog, NCO.g.prog, true); else NCO.g.prog.innerHTML = "";
  NCO.drawPath(NCO.out, NCO.g.path, false);
  NCO.drawMarks(NCO.g.marks);
  NCO.drawSelection(NCO.g.sel);
  svg.dataset.scale = T.k; svg.dataset.tx = T.tx; svg.dataset.ty = T.ty;
  svg.dataset.view = NCO.state.view;
};

NCO.buildToolbar = function () {
  const tb = document.getElementById("nco-toolbar");
  let s = "";
  ["xy", "zx", "yz", "iso"].forEach(function (v) {
    s += '<button data-view="' + v + '" title="view ' + NCO.VIEWS[v].name + '">' + v.toUpperCase() + "</button>";
  });
  s += '<span class="sep"></span><button data-act="in" title="zoom in (+)">+</button>' +
       '<button data-act="out" title="zoom out (-)">\u2212</button><button data-act="fit" title="fit (f)">fit</button>' +
       '<span class="sep"></span><button data-act="prev" title="previous block (\u2191, p)">\u25b2 block</button>' +
       '<button data-act="next" title="next block (\u2193, n)">\u25bc block</button><span class="sep"></span>' +
       '<label>colour <select id="nco-colour"><option value="motion">by motion</option>' +
       '<option value="z">by Z</option><option value="tool">by tool</option></select></label>' +
       '<label><input type="checkbox" id="nco-prog-on" checked> programmed</label><span class="sep"></span>' +
       '<span class="legend"><span><i style="border-color:#1565c0"></i> feed</span>' +
       '<span><i style="border-color:#e53935;border-top-style:dashed"></i> G0</span>' +
       '<span><i style="border-color:#00a152;border-top-width:3px"></i> inserted</span>' +
       '<span><i style="border-color:#9e9e9e;border-top-style:dotted"></i> programmed</span></span>';
  tb.innerHTML = s;
  tb.addEventListener("click", function (e) {
    const b = e.target.closest("button");
    if (!b) return;
    if (b.dataset.view) NCO.setView(b.dataset.view);
    const a = b.dataset.act;
    if (a === "in") NCO.zoom(1.5, NCO.T.w / 2, NCO.T.h / 2);
    if (a === "out") NCO.zoom(1 / 1.5, NCO.T.w / 2, NCO.T.h / 2);
    if (a === "fit") { NCO.fit(); NCO.redraw(); }
    if (a === "next") NCO.step(1);
    if (a === "prev") NCO.step(-1);
  });
  document.getElementById("nco-colour").addEventListener("change", function (e) {
    NCO.state.colour = e.target.value; NCO.redraw();
  });
  document.getElementById("nco-prog-on").addEventListener("change", function (e) {
    NCO.state.programmed = e.target.checked; NCO.redraw();
  });
};

NCO.setView = function (v, now) {
  NCO.state.view = v;
  document.querySelectorAll("#nco-toolbar button[data-view]").forEach(function (b) {
    b.classList.toggle("active", b.dataset.view === v);
  });
  NCO.fit();
  if (now) NCO.drawNow(); else NCO.redraw();
};

// Selects the block (file, line): its segments in the drawing and the list, its line in the
// program text. `focus`: the segment clicked (the tool is drawn at its end); `from`: where the
// click was (that view is not scrolled).
NCO.selectLine = function (file, line, focus, from) {
  const segs = NCO.segmentsOf(NCO.out, file, line);
  NCO.state.sel = { file: file, line: line, segs: segs, focus: focus >= 0 ? focus : segs.length ? segs[0] : -1 };
  NCO.showFile(file);
  if (from !== "text") NCO.src.show(line - 1); else NCO.src.refresh();
  if (segs.length && from !== "list") NCO.list.show(segs[0]); else NCO.list.refresh();
  if (from !== "drawing" && segs.length) NCO.reveal(segs);
  NCO.drawSelection(NCO.g.sel);
  const p = NCO.out, i = NCO.state.sel.focus;
  NCO.status((NCO.data.files[file] || "") + ":" + line + " \u2014 " + segs.length + " segment" +
             (segs.length === 1 ? "" : "s") + (i >= 0 ? ", end " + NCO.point(p, i) : ""));
};

// Pans so that the segments are in view (when none of them is).
NCO.reveal = function (segs) {
  const q = [0, 0], T = NCO.T;
  for (const i of segs) {
    NCO.screen(NCO.out.x[i], NCO.out.y[i], NCO.out.z[i], q);
    if (q[0] >= 0 && q[0] <= T.w && q[1] >= 0 && q[1] <= T.h) return;
  }
  const i = segs[0];
  NCO.screen(NCO.out.x[i], NCO.out.y[i], NCO.out.z[i], q);
  NCO.pan(T.w / 2 - q[0], T.h / 2 - q[1]);
};

// The next (+1) or previous (-1) block with motion after / before the selection.
NCO.step = function (dir) {
  const p = NCO.out, sel = NCO.state.sel;
  if (!p.n) return;
  let i;
  if (!sel || !sel.segs.length) i = dir > 0 ? 0 : p.n - 1;
  else {
    i = dir > 0 ? sel.segs[sel.segs.length - 1] + 1 : sel.segs[0] - 1;
    while (i >= 0 && i < p.n && p.file[i] === sel.file && p.line[i] === sel.line) i += dir;
    if (i < 0 || i >= p.n) return;
  }
  NCO.selectLine(p.file[i], p.line[i], i, "key");
};

NCO.point = function (p, i) {
  return "X" + NCO.fmt(p.x[i]) + " Y" + NCO.fmt(p.y[i]) + " Z" + NCO.fmt(p.z[i]);
};

NCO.status = function (text) { document.getElementById("nco-status").textContent = text; };

// What the hover shows of segment i.
NCO.describe = function (i) {
  const p = NCO.out, f = p.file[i], line = p.line[i], text = NCO.lineText(f, line - 1).trim();
  let s = (NCO.data.files[f] || "") + ":" + line + "  " + text.slice(0, 80) + "\n" +
          NCO.motionName(p, i) + (NCO.inserted[i] ? " (inserted by compensation)" : "") +
          "  end " + NCO.point(p, i) + "\n";
  s += NCO.hasFeed(p, i) ? "feed F" + NCO.fmt(p.feed[i]) + " " + NCO.UNIT[p.unit[i]] : "rapid traverse";
  const j = NCO.match[i];
  if (j >= 0) s += "\nprogrammed end " + NCO.point(NCO.prog, j);
  if (j === -2) s += "\nprogrammed end the same (no compensation)";
  const t = p.tool[i] >= 0 ? NCO.data.tools[p.tool[i]] : null;
  if (t) s += "\ntool T" + t.t + " D" + t.d + " R" + NCO.fmt(t.r);
  return s;
};

NCO.initDrawingEvents = function () {
  const svg = NCO.svg, tip = document.getElementById("nco-tip");
  let drag = null, hoverPending = null;
  const local = function (e) {
    const r = svg.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  svg.addEventListener("wheel", function (e) {
    e.preventDefault();
    const q = local(e);
    NCO.zoom(Math.pow(1.0015, -e.deltaY), q[0], q[1]);
  }, { passive: false });
  svg.addEventListener("mousedown", function (e) {
    drag = { x: e.clientX, y: e.clientY, moved: false };
  });
  window.addEventListener("mousemove", function (e) {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.abs(dx) + Math.abs(dy) < 4) return;
    drag.moved = true; svg.classList.add("panning");
    drag.x = e.clientX; drag.y = e.clientY;
    NCO.pan(dx, dy);
  });
  window.addEventListener("mouseup", function (e) {
    if (!drag) return;
    const moved = drag.moved;
    drag = null; svg.classList.remove("panning");
    if (moved || !svg.contains(e.target)) return;
    const el = e.target.closest("[data-line]");
    let i = el && el.dataset.i !== undefined ? +el.dataset.i : -1;
    if (i < 0 && el && el.classList.contains("dec") === false && el.dataset.file !== undefined) {
      NCO.selectLine(+el.dataset.file, +el.dataset.line, -1, "drawing");  // a warning or alarm mark
      return;
    }
    if (i < 0 || (el && el.classList.contains("pseg"))) {
      const q = local(e);
      const near = NCO.nearest(q[0], q[1], 8);
      if (near >= 0) i = near; else if (el && el.classList.contains("pseg")) {
        NCO.selectLine(+el.dataset.file, +el.dataset.line, -1, "drawing");
        return;
      }
    }
    if (i >= 0) NCO.selectLine(NCO.out.file[i], NCO.out.line[i], i, "drawing");
  });
  svg.addEventListener("mousemove", function (e) {
    if (drag) return;
    hoverPending = e;
    requestAnimationFrame(function () {
      const ev = hoverPending;
      if (!ev) return;
      hoverPending = null;
      const el = ev.target.closest && ev.target.closest("[data-i]");
      let i = el ? +el.dataset.i : -1;
      if (i < 0 && NCO.svg.dataset.mode === "exact") { const q = local(ev); i = NCO.nearest(q[0], q[1], 6); }
      if (i < 0) { tip.hidden = true; return; }
      const q = local(ev);
      tip.textContent = NCO.describe(i);
      tip.hidden = false;
      tip.style.left = Math.min(q[0] + 14, NCO.T.w - 260) + "px";
      tip.style.top = q[1] + 40 + "px";
    });
  });
  svg.addEventListener("mouseleave", function () { tip.hidden = true; });
};

NCO.initKeys = function () {
  document.addEventListener("keydown", function (e) {
    if (e.target.tagName === "INPUT" || e.target.tagName === "SELECT") return;
    const k = e.key;
    if (k === "ArrowDown" || k === "n" || k === "j") { NCO.step(1); e.preventDefault(); }
    else if (k === "ArrowUp" || k === "p" || k === "k") { NCO.step(-1); e.preventDefault(); }
    else if (k === "+" || k === "=") NCO.zoom(1.5, NCO.T.w / 2, NCO.T.h / 2);
    else if (k === "-") NCO.zoom(1 / 1.5, NCO.T.w / 2, NCO.T.h / 2);
    else if (k === "f") { NCO.fit(); NCO.redraw(); }
  });
  document.getElementById("nco-info").addEventListener("click", function (e) {
    const g = e.target.closest(".nco-goto");
    if (g && +g.dataset.file >= 0) NCO.selectLine(+g.dataset.file, +g.dataset.line, -1, "info");
  });
};

NCO.start = function () {
  const t0 = performance.now();
  NCO.load();
  NCO.svg = document.getElementById("nco-svg");
  NCO.g = {};
  ["axes", "prog", "path", "marks", "sel"].forEach(function (id) {
    const g = document.createElementNS("http://www.w3.org/2000/svg", "g");
    g.id = "nco-" + (id === "path" ? "out" : id);
    NCO.svg.appendChild(g); NCO.g[id] = g;
  });
  NCO.state.view = NCO.data.view; NCO.state.colour = "motion"; NCO.state.programmed = true;
  NCO.state.sel = null;
  NCO.buildToolbar(); NCO.initSource(); NCO.initSegments();
  NCO.initDrawingEvents(); NCO.initKeys();
  const t1 = performance.now();
  NCO.size(); NCO.setView(NCO.state.view, true);
  NCO.times.draw = Math.round(performance.now() - t1);
  window.addEventListener("resize", function () { NCO.size(); NCO.redraw(); });
  NCO.status(NCO.out.n + " segments, " + NCO.data.files.length + " files; click a segment or a line, " +
             "wheel to zoom, drag to pan, \u2191/\u2193 for the blocks");
  document.body.dataset.ready = "1";
  document.body.dataset.startMs = Math.round(performance.now() - t0);
  document.body.dataset.times = JSON.stringify(NCO.times);  // parse, decode, draw (ms)
};

NCO.start();
