// ncoffset HTML report: the program text (every file of the run, with line numbers and syntax
// colouring) and the segment list, both virtualised: only the rows in view are elements, so a
// program of a million lines opens at once.
NCO.ROW = 16;  // px, as .ln / .sr in report.css

NCO.VList = function (el, render) {
  this.el = el; this.render = render; this.count = 0;
  this.spacer = document.createElement("div");
  this.rows = document.createElement("div"); this.rows.className = "rows";
  el.appendChild(this.spacer); el.appendChild(this.rows);
  const self = this;
  let pending = false;
  el.addEventListener("scroll", function () {
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () { pending = false; self.refresh(); });
  });
};
NCO.VList.prototype.setCount = function (n) {
  this.count = n;
  this.spacer.style.height = n * NCO.ROW + "px";
  this.refresh();
};
NCO.VList.prototype.refresh = function () {
  const top = this.el.scrollTop, h = this.el.clientHeight || 400;
  const a = Math.max(0, Math.floor(top / NCO.ROW) - 20);
  const b = Math.min(this.count, Math.ceil((top + h) / NCO.ROW) + 20);
  let s = "";
  for (let i = a; i < b; ++i) s += this.render(i);
  this.rows.style.top = a * NCO.ROW + "px";
  this.rows.innerHTML = s;
};
// Scrolls row i into the middle unless it is in view already; the rows are drawn at once.
NCO.VList.prototype.show = function (i) {
  const top = this.el.scrollTop, h = this.el.clientHeight || 400, y = i * NCO.ROW;
  if (y < top || y + NCO.ROW > top + h) this.el.scrollTop = Math.max(0, y - h / 2);
  this.refresh();
};

// Syntax colouring of one line of SINUMERIK text: comments, strings, block numbers, G, M, T/D
// words and the keywords of control structures, calls and frames.
NCO.TOKENS = new RegExp(
  '(;.*$)|("[^"]*"?)|(^\\s*(?:/\\d?\\s*)?(?:N\\d+|:\\d+)\\b)|(\\bG\\d+\\b)|(\\bM\\d*=?\\d+\\b)|' +
  '(\\b[TD]\\d*=?\\d+\\b)|(\\b(?:IF|ELSE|ENDIF|WHILE|ENDWHILE|FOR|TO|ENDFOR|REPEAT|REPEATB|UNTIL|' +
  'LOOP|ENDLOOP|GOTOF|GOTOB|GOTOC|GOTO|CASE|OF|DEFAULT|DEF|PROC|RET|MSG|CALL|MCALL|PCALL|EXTERN|' +
  'TRANS|ATRANS|ROT|AROT|SCALE|ASCALE|MIRROR|AMIRROR|SUPA|G500|STOPRE|DEFINE|AS|SAVE|VAR|AND|OR|' +
  'NOT|B_AND|B_OR|DIV|MOD)\\b)', "gi");
NCO.CLASSES = ["tk-c", "tk-s", "tk-n", "tk-g", "tk-m", "tk-t", "tk-k"];

NCO.highlight = function (text) {
  let out = "", at = 0, m;
  NCO.TOKENS.lastIndex = 0;
  while ((m = NCO.TOKENS.exec(text)) !== null) {
    if (m[0] === "") { NCO.TOKENS.lastIndex++; continue; }
    let g = 1;
    while (m[g] === undefined) ++g;
    out += NCO.escape(text.slice(at, m.index)) + '<span class="' + NCO.CLASSES[g - 1] + '">' +
           NCO.escape(m[0]) + "</span>";
    at = m.index + m[0].length;
    if (g === 1) break;  // a comment runs to the end of the line
  }
  return out + NCO.escape(text.slice(at));
};

// Lines with warnings and the alarm, per file: "file:line" -> class.
NCO.lineMarks = function () {
  const marks = {};
  NCO.data.notes.forEach(function (n) { if (n[2]) marks[n[0] + ":" + n[1]] = "warn"; });
  const al = NCO.data.alarm;
  if (al) marks[al[0] + ":" + al[1]] = "alarm";
  return marks;
};

NCO.initSource = function () {
  const tabs = document.getElementById("nco-tabs"), files = NCO.data.files;
  NCO.marks = NCO.lineMarks();
  let s = "";
  files.forEach(function (name, f) {
    s += '<button data-file="' + f + '" title="' + NCO.escape(name) + '">' +
         NCO.escape(name.replace(/^.*[\\/]/, "")) + "</button>";
  });
  tabs.innerHTML = s;
  tabs.addEventListener("click", function (e) {
    const b = e.target.closest("button");
    if (b) NCO.showFile(+b.dataset.file);
  });
  NCO.src = new NCO.VList(document.getElementById("nco-src"), function (i) {
    const f = NCO.state.file, line = i + 1, text = NCO.lineText(f, i);
    const sel = NCO.state.sel, key = f + ":" + line;
    let cls = "ln";
    if (sel && sel.file === f && sel.line === line) cls += " selected";
    if (NCO.marks[key]) cls += " " + NCO.marks[key];
    return '<div class="' + cls + '" data-file="' + f + '" data-line="' + line + '"><span class="no">' +
           line + "</span>" + NCO.highlight(text) + "</div>";
  });
  NCO.src.el.addEventListener("click", function (e) {
    const ln = e.target.closest(".ln");
    if (ln) NCO.selectLine(+ln.dataset.file, +ln.dataset.line, -1, "text");
  });
  NCO.state.file = -1;
  NCO.showFile(NCO.out.n ? NCO.out.file[0] : 0);
};

NCO.showFile = function (f) {
  if (f === NCO.state.file || f < 0 || f >= NCO.data.files.length) return;
  NCO.state.file = f;
  document.querySelectorAll("#nco-tabs button").forEach(function (b) {
    b.classList.toggle("active", +b.dataset.file === f);
  });
  NCO.src.el.scrollTop = 0;
  NCO.src.setCount(NCO.fileLines(f).length);
};

// The segment list: one row per output segment.
NCO.initSegments = function () {
  const p = NCO.out;
  NCO.list = new NCO.VList(document.getElementById("nco-seglist"), function (i) {
    const sel = NCO.state.sel, name = NCO.data.files[p.file[i]] || "#" + p.file[i];
    const on = sel && sel.file === p.file[i] && sel.line === p.line[i];
    return '<div class="sr' + (on ? " selected" : "") + '" data-i="' + i + '" data-file="' + p.file[i] +
           '" data-line="' + p.line[i] + '"><span>' + (i + 1) + '</span><span class="w">' +
           NCO.escape(name.replace(/^.*[\\/]/, "")) + ":" + p.line[i] + "</span><span>" +
           NCO.motionName(p, i) + (NCO.inserted[i] ? "*" : "") + "</span><span>" +
           NCO.fmt(p.x[i]) + "</span><span>" + NCO.fmt(p.y[i]) + "</span><span>" + NCO.fmt(p.z[i]) +
           "</span><span>" + (NCO.hasFeed(p, i) ? NCO.fmt(p.feed[i]) : "") + "</span></div>";
  });
  NCO.list.el.addEventListener("click", function (e) {
    const r = e.target.closest(".sr");
    if (r) NCO.selectLine(+r.dataset.file, +r.dataset.line, +r.dataset.i, "list");
  });
  NCO.list.setCount(p.n);
};
