// ecnc view: an orthographic 3D view of a toolpath on the browser's 2D canvas, with a move-by-move player.
// Everything it needs is in this page; it fetches nothing.
"use strict";
(function () {
  const status = document.getElementById("status");
  const errors = [];
  function report(message) {
    errors.push(String(message));
    status.dataset.errors = String(errors.length);
    status.textContent = errors.join("\n");
  }
  window.addEventListener("error", (event) => report(event.message));
  window.addEventListener("unhandledrejection", (event) => report(event.reason));

  // `ecnc view --diff OLD NEW`: the page holds both jobs; #job=old shows OLD, the toggle reloads with the other
  const otherData = document.getElementById("job-data-old");
  const showOld = otherData !== null && new URLSearchParams(location.hash.slice(1)).get("job") === "old";
  const D = JSON.parse((showOld ? otherData : document.getElementById("job-data")).textContent);

  function decode(text, Type) {
    if (text === null || text === undefined) return null;
    const raw = atob(text);
    const bytes = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
    return new Type(bytes.buffer);
  }

  const points = decode(D.points, Float32Array);
  const first = decode(D.first, Int32Array);
  const last = decode(D.last, Int32Array);
  const kind = decode(D.kind, Uint8Array);
  const tool = decode(D.tool, Int32Array);
  const line = decode(D.line, Int32Array);
  const file = decode(D.file, Uint16Array);
  const feed = decode(D.feed, Float32Array);
  const merged = decode(D.merged, Int32Array);
  const time = decode(D.time, Float32Array);    // planned end of each move, seconds from the start
  const speed = decode(D.speed, Float32Array);  // the planner's top speed, mm/min
  const index = new Int32Array(merged.length);  // the job's move number (from 0) each shown move ends at
  for (let i = 0, total = -1; i < merged.length; i++) index[i] = total += merged[i];
  const abc = decode(D.abc, Float32Array);
  const joints = decode(D.joints, Float32Array);
  const count = kind.length;
  const rapidKinds = new Set(D.rapidKinds);
  const isRapid = (i) => rapidKinds.has(kind[i]);

  // `ecnc view --diff`: the other job drawn under this one, and the changes (ecnc diff's) by move number
  const diffBlock = document.getElementById("diff-data");
  const C = diffBlock ? JSON.parse(diffBlock.textContent) : null;
  const O = otherData !== null ? JSON.parse((showOld ? document.getElementById("job-data") : otherData).textContent) : null;
  const otherPoints = O ? decode(O.points, Float32Array) : null;
  const otherFirst = O ? decode(O.first, Int32Array) : null;
  const otherLast = O ? decode(O.last, Int32Array) : null;
  const changeOf = new Int32Array(count).fill(-1);  // the change each shown move is part of (-1: none)
  if (C) {
    C.changes.forEach((change, n) => {
      const span = showOld ? (change.kind === "removed" || change.kind === "replaced" ? change.old : null) : change.new;
      if (!span) return;
      for (let i = 0; i < count; i++) {
        if (index[i] >= span[0] && index[i] - merged[i] + 1 <= span[1] && changeOf[i] < 0) changeOf[i] = n;
      }
    });
  }

  // ---------------------------------------------------------------- camera
  // yaw, pitch, roll (deg); lathe: seen from +Y and turned a quarter, so Z runs across and X up
  const VIEWS = { top: [0, 0, 0], front: [0, -90, 0], side: [-90, -90, 0], iso: [45, -54.7356, 0],
                  lathe: [180, -90, -90] };
  const cam = { yaw: 0, pitch: 0, roll: 0, scale: 1, u: 0, v: 0 };
  // what a drag turns about: the centre of the part's box (of the work zero for a job with no moves)
  const pivot = D.part ? [0, 1, 2].map((a) => (D.part[0][a] + D.part[1][a]) / 2) : D.workZero.slice(0, 3);
  const canvas = document.getElementById("view");
  const ctx = canvas.getContext("2d");
  let projected = new Float32Array(points.length / 3 * 2);
  let projectedFor = "";

  function project(x, y, z) {
    const cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw), cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch);
    const cr = Math.cos(cam.roll), sr = Math.sin(cam.roll);
    const u = x * cy - y * sy, v = (x * sy + y * cy) * cp - z * sp;
    return [u * cr - v * sr, u * sr + v * cr];
  }

  let otherProjected = otherPoints ? new Float32Array(otherPoints.length / 3 * 2) : null;

  function projectInto(source, target) {
    const cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw), cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch);
    const cr = Math.cos(cam.roll), sr = Math.sin(cam.roll);
    for (let p = 0, q = 0; p < source.length; p += 3, q += 2) {
      const x = source[p], y = source[p + 1], z = source[p + 2];
      const u = x * cy - y * sy, v = (x * sy + y * cy) * cp - z * sp;
      target[q] = u * cr - v * sr;
      target[q + 1] = u * sr + v * cr;
    }
  }

  function projectAll() {
    const key = cam.yaw + "," + cam.pitch + "," + cam.roll;
    if (key === projectedFor) return;
    projectInto(points, projected);
    if (otherPoints) projectInto(otherPoints, otherProjected);
    projectedFor = key;
  }

  function size() {
    const ratio = window.devicePixelRatio || 1;
    const w = canvas.clientWidth, h = canvas.clientHeight;
    if (canvas.width !== Math.round(w * ratio) || canvas.height !== Math.round(h * ratio)) {
      canvas.width = Math.round(w * ratio);
      canvas.height = Math.round(h * ratio);
    }
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    return [w, h];
  }

  function toScreen(u, v, w, h) {
    return [w / 2 + (u - cam.u) * cam.scale, h / 2 - (v - cam.v) * cam.scale];
  }

  function fit() {
    projectAll();
    let lowU = Infinity, lowV = Infinity, highU = -Infinity, highV = -Infinity;
    const extend = (u, v) => {
      lowU = Math.min(lowU, u); highU = Math.max(highU, u); lowV = Math.min(lowV, v); highV = Math.max(highV, v);
    };
    for (let q = 0; q < projected.length; q += 2) extend(projected[q], projected[q + 1]);
    extend(...project(...D.workZero));
    if (D.part) {  // the part's box is drawn: in the iso view its far corners can lie outside the path
      for (let k = 0; k < 8; k++) extend(...project(...[0, 1, 2].map((a) => D.part[(k >> a) & 1][a])));
    }
    if (B) {  // the bar being turned (ecnc view --bar), from its far end (or the chuck's) to its face
      const far = B.chuck !== null ? B.z0 - 0.05 * B.n * B.slice : B.z0;
      for (const z of [far, B.z0 + B.n * B.slice]) for (const x of [0, 1.15 * B.radius]) extend(...project(x, 0, z));
    }
    if (!isFinite(lowU)) { lowU = lowV = -10; highU = highV = 10; }
    const [w, h] = size();
    cam.u = (lowU + highU) / 2;
    cam.v = (lowV + highV) / 2;
    cam.scale = 0.88 * Math.min(w / Math.max(highU - lowU, 1e-3), h / Math.max(highV - lowV, 1e-3));
    if (!isFinite(cam.scale) || cam.scale <= 0) cam.scale = 1;
  }

  function setView(name) {
    [cam.yaw, cam.pitch, cam.roll] = VIEWS[name].map((deg) => deg * Math.PI / 180);
    document.querySelectorAll("[data-view]").forEach((b) => b.classList.toggle("active", b.dataset.view === name));
    fit();
    draw();
  }

  // ---------------------------------------------------------------- colours and groups
  const colorMode = document.getElementById("color-mode");
  let groups = [];

  function toolColor(t) {
    return D.toolColors[Math.max(D.tools.indexOf(t), 0) % D.toolColors.length];
  }

  function feedBuckets() {
    let low = Infinity, high = -Infinity;
    for (let i = 0; i < count; i++) if (!isRapid(i)) { low = Math.min(low, feed[i]); high = Math.max(high, feed[i]); }
    return [low, high];
  }

  const FEED_SHADES = ["#440154", "#3b528b", "#21918c", "#5ec962", "#b5de2b", "#fde725"];

  function buildGroups() {
    const mode = colorMode.value;
    const byKey = new Map();
    const [low, high] = feedBuckets();
    for (let i = 0; i < count; i++) {
      let key, color, label;
      if (mode === "changes") {
        const n = changeOf[i];
        const change = n >= 0 ? C.changes[n] : null;
        key = change ? change.kind : isRapid(i) ? "rapid, unchanged" : "unchanged";
        color = change ? change.color : C.sameColor;
        label = change ? C.kinds[change.kind][1] : key;
        if (!byKey.has(key)) byKey.set(key, { key, color, label, rapid: !change && isRapid(i), moves: [] });
        byKey.get(key).moves.push(i);
        continue;
      } else if (isRapid(i) && mode !== "kind") {
        key = "rapid"; color = D.kindColors.rapid; label = "rapid";
      } else if (mode === "kind") {
        const name = D.kinds[kind[i]];
        key = name; color = D.kindColors[name]; label = name;
      } else if (mode === "tool") {
        key = "T" + tool[i]; color = toolColor(tool[i]); label = tool[i] ? "T" + tool[i] : "no tool";
      } else {
        const span = high - low;
        const b = span > 0 ? Math.min(FEED_SHADES.length - 1, Math.floor((feed[i] - low) / span * FEED_SHADES.length)) : 0;
        const from = low + span * b / FEED_SHADES.length, to = low + span * (b + 1) / FEED_SHADES.length;
        key = "F" + b; color = FEED_SHADES[b];
        label = span > 0 ? "F " + Math.round(from) + "\u2013" + Math.round(to) + " mm/min" : "F " + Math.round(low) + " mm/min";
      }
      if (!byKey.has(key)) byKey.set(key, { key, color, label, rapid: isRapid(i), moves: [] });
      byKey.get(key).moves.push(i);
    }
    groups = [...byKey.values()].sort((a, b) => (a.rapid === b.rapid ? a.key.localeCompare(b.key, undefined, { numeric: true }) : a.rapid ? -1 : 1));
    legend();
  }

  function legend() {
    const list = document.getElementById("legend");
    list.replaceChildren();
    const entry = (color, dash, text) => {
      const item = document.createElement("li");
      item.innerHTML = '<svg width="28" height="10"><line x1="1" y1="5" x2="27" y2="5" stroke-width="2"/></svg>';
      const stroke = item.querySelector("line");
      stroke.setAttribute("stroke", color);
      if (dash) stroke.setAttribute("stroke-dasharray", dash);
      item.append(text);
      list.append(item);
    };
    if (O) entry(C ? C.oldColor : "#cfcfcf", "", (showOld ? "NEW" : "OLD") + " (the other job)");
    groups.forEach((g) => entry(g.color, g.rapid ? "4 3" : "", g.label));
    entry("#444", "1 2", "part bounding box");
    if (D.limits) entry("#b22222", "6 3 1 3", "machine limits (cnc.ini)");
    entry("#000", "", "work zero (circle), tool (red dot)");
  }

  // ---------------------------------------------------------------- drawing
  const slider = document.getElementById("slider");
  const showRapids = document.getElementById("show-rapids");
  const showFuture = document.getElementById("show-future");
  let current = count - 1;

  function tracePolyline(i, w, h) {
    const [x0, y0] = toScreen(projected[2 * first[i]], projected[2 * first[i] + 1], w, h);
    let x = x0, y = y0, extent = 0;
    ctx.moveTo(x, y);
    for (let p = first[i] + 1; p <= last[i]; p++) {
      [x, y] = toScreen(projected[2 * p], projected[2 * p + 1], w, h);
      ctx.lineTo(x, y);
      extent = Math.max(extent, Math.abs(x - x0), Math.abs(y - y0));
    }
    if (extent < 0.5 && !isRapid(i)) {  // a feed straight at the viewer (a drilled hole from the top): a ring
      ctx.moveTo(x0 + 3, y0);
      ctx.arc(x0, y0, 3, 0, 2 * Math.PI);
    }
  }

  function box(corners, color, dash, w, h) {
    if (!corners) return;
    const [lo, hi] = corners;
    const corner = (k) => [k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]];
    ctx.beginPath();
    for (let k = 0; k < 8; k++) {
      for (const bit of [1, 2, 4]) {
        if (k & bit) continue;
        const a = toScreen(...project(...corner(k)), w, h), b = toScreen(...project(...corner(k | bit)), w, h);
        ctx.moveTo(a[0], a[1]);
        ctx.lineTo(b[0], b[1]);
      }
    }
    ctx.strokeStyle = color;
    ctx.lineWidth = 1;
    ctx.setLineDash(dash);
    ctx.stroke();
    ctx.setLineDash([]);
  }

  function triad(w, h) {
    const origin = [46, h - 46];
    const names = ["X", "Y", "Z"], colors = ["#d62728", "#2ca02c", "#1f77b4"];
    for (let a = 0; a < 3; a++) {
      const unit = [0, 0, 0];
      unit[a] = 1;
      const [u, v] = project(...unit);
      if (Math.hypot(u, v) < 0.05) continue;  // pointing at the viewer
      ctx.beginPath();
      ctx.moveTo(...origin);
      ctx.lineTo(origin[0] + 30 * u, origin[1] - 30 * v);
      ctx.strokeStyle = colors[a];
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.fillStyle = colors[a];
      ctx.fillText(names[a], origin[0] + 38 * u - 3, origin[1] - 38 * v + 4);
    }
  }

  // ---------------------------------------------------------------- the stock being cut (ecnc view --stock)
  // Coarse height maps every so many moves (edingcnc_lang/sim/frames.py); the one for the move
  // shown is drawn under the path, one shaded square per block, far ones first.
  const stockBlock = document.getElementById("stock-data");
  const S = stockBlock ? JSON.parse(stockBlock.textContent) : null;
  const stockHeights = S ? decode(S.heights, Uint16Array) : null;
  const STOCK_SHADES = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
  let stockOrder = null, stockKey = "";
  function stockShade(level, light) {
    const f = Math.min(0.9999, Math.max(0, level)) * (STOCK_SHADES.length - 1), k = Math.floor(f), t = f - k;
    const c = STOCK_SHADES[k].map((v, n) => (v + (STOCK_SHADES[k + 1][n] - v) * t) * light);
    return "rgb(" + c.map(Math.round).join(",") + ")";
  }
  function drawStock(w, h) {
    if (!S) return;
    const reached = current >= 0 ? index[current] + 1 : 0;  // moves done once the shown one ends
    let frame = 0;
    while (frame + 1 < S.moves.length && S.moves[frame + 1] <= reached) frame++;
    const nx = S.nx, ny = S.ny, base = frame * nx * ny, span = S.top - S.bottom;
    const sy = Math.sin(cam.yaw), cy = Math.cos(cam.yaw), sp = Math.sin(cam.pitch);
    const key = cam.yaw + "," + cam.pitch;
    if (key !== stockKey) {
      const depth = new Float64Array(nx * ny);
      for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) depth[j * nx + i] = (i * sy + j * cy) * sp;
      stockOrder = Array.from(depth.keys()).sort((a, b) => depth[a] - depth[b]);
      stockKey = key;
    }
    // the walls that face the viewer: +X, -X, +Y, -Y sides of a column (normal . view > 0)
    const walls = [[1, 0, sy * sp], [-1, 0, -sy * sp], [0, 1, cy * sp], [0, -1, -cy * sp]].filter((f) => f[2] > 1e-9);
    const level = (i, j) => stockHeights[base + Math.min(ny - 1, Math.max(0, j)) * nx + Math.min(nx - 1, Math.max(0, i))] / 65535;
    const polygon = (corners, colour) => {
      ctx.beginPath();
      corners.forEach(([x, y, z], n) => {
        const [sx, sy2] = toScreen(...project(x, y, z), w, h);
        if (n) ctx.lineTo(sx, sy2); else ctx.moveTo(sx, sy2);
      });
      ctx.fillStyle = colour;
      ctx.fill();
    };
    for (const c of stockOrder) {
      const i = c % nx, j = (c - i) / nx, q = level(i, j), z = S.bottom + q * span;
      const gx = (level(i + 1, j) - level(i - 1, j)) * span / (2 * S.cell), gy = (level(i, j + 1) - level(i, j - 1)) * span / (2 * S.cell);
      const light = 0.55 + 0.45 * Math.max(0, (-gx * 0.5 + gy * 0.5 + 1) / Math.sqrt(1.5 * (1 + gx * gx + gy * gy)));
      const x0 = S.x0 + i * S.cell, y0 = S.y0 + j * S.cell, x1 = x0 + S.cell, y1 = y0 + S.cell;
      for (const [fx, fy] of walls) {  // a column down to the bottom: nearer columns paint over it
        const x = fx > 0 ? x1 : x0, y = fy > 0 ? y1 : y0;
        const ends = fx ? [[x, y0], [x, y1]] : [[x0, y], [x1, y]];
        polygon([[...ends[0], z], [...ends[1], z], [...ends[1], S.bottom], [...ends[0], S.bottom]], stockShade(q, fx ? 0.5 : 0.4));
      }
      polygon([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]], stockShade(q, light));
    }
  }

  // ---------------------------------------------------------------- the bar being turned (ecnc view --bar)
  // Its profile every so many moves (edingcnc_lang/sim/bar_frames.py), the one for the move shown
  // drawn as the half section in the work's ZX plane (X a radius, as the path is), over the bar as it
  // was, the chuck beyond its face and the findings of the moves made so far.
  const barBlock = document.getElementById("bar-data");
  const B = barBlock ? JSON.parse(barBlock.textContent) : null;
  const barRadii = B ? decode(B.radii, Uint16Array) : null;
  const BAR_MARKS = { rapid_into_stock: "#d62728", spindle_off: "#9467bd", holder: "#8c564b", chuck: "#2ca02c" };
  function drawBar(w, h) {
    if (!B) return;
    const reached = current >= 0 ? index[current] + 1 : 0;
    let frame = 0;
    while (frame + 1 < B.moves.length && B.moves[frame + 1] <= reached) frame++;
    const n = B.n, base = frame * 2 * n, end = B.z0 + n * B.slice;
    const outline = (corners) => corners.forEach(([x, z], k) => {
      const [u, v] = toScreen(...project(x, 0, z), w, h);
      if (k) ctx.lineTo(u, v); else ctx.moveTo(u, v);
    });
    ctx.beginPath();
    outline([[0, B.z0], [B.radius, B.z0], [B.radius, end], [0, end]]);
    ctx.fillStyle = "#e4e4e4";
    ctx.fill();
    if (B.chuck !== null) {
      ctx.beginPath();
      outline([[0, B.z0 - 0.05 * (end - B.z0)], [1.15 * B.radius, B.z0 - 0.05 * (end - B.z0)],
               [1.15 * B.radius, B.chuck], [0, B.chuck]]);
      ctx.fillStyle = "rgba(127, 127, 127, 0.35)";
      ctx.fill();
    }
    ctx.beginPath();
    for (let i = 0; i < n; i++) {
      const outer = barRadii[base + i] / 65535 * B.radius, inner = barRadii[base + n + i] / 65535 * B.radius;
      if (outer - inner < 1e-6) continue;
      const z0 = B.z0 + i * B.slice, z1 = z0 + B.slice;
      outline([[inner, z0], [outer, z0], [outer, z1], [inner, z1]]);
    }
    ctx.fillStyle = "#4c72b0";
    ctx.fill();
    for (const f of B.findings) {
      if (f.move >= reached) continue;
      const [u, v] = toScreen(...project(f.x, 0, f.z), w, h);
      ctx.beginPath();
      ctx.arc(u, v, 5, 0, 2 * Math.PI);
      ctx.fillStyle = BAR_MARKS[f.kind] || "#d62728";
      ctx.fill();
      ctx.fillText(f.line + " " + f.kind, u + 7, v - 7);
    }
  }

  // ---------------------------------------------------------------- the bar on a rotary axis (ecnc view --stock cylinder:)
  // Its unrolled depth map every so many moves (edingcnc_lang/sim/rotary_frames.py): depth below the
  // bar's surface over the axial position (across) and the bar's own angle (up), as ecnc sim -o draws
  // it, in a panel under the 3D view; the tool where the move shown leaves it, the findings so far.
  const rotaryBlock = document.getElementById("rotary-data");
  const R = rotaryBlock ? JSON.parse(rotaryBlock.textContent) : null;
  const rotaryDepths = R ? decode(R.depths, Uint8Array) : null;
  const rotaryTips = R ? decode(R.tips, Float32Array) : null;
  const DEPTH_SHADES = [[252, 253, 191], [252, 137, 97], [183, 55, 121], [81, 18, 124], [0, 0, 4]];  // magma_r
  const map = R ? document.createElement("canvas") : null;
  let mapImage = null, mapFrame = -1;
  if (R) {
    map.id = "unrolled";
    map.setAttribute("aria-label", "the bar unrolled: depth over its axis and angle");
    document.getElementById("stage").classList.add("with-map");
    document.getElementById("stage").append(map);
  }
  function depthShade(level) {
    const f = Math.min(0.9999, Math.max(0, level)) * (DEPTH_SHADES.length - 1), k = Math.floor(f), t = f - k;
    return DEPTH_SHADES[k].map((v, n) => Math.round(v + (DEPTH_SHADES[k + 1][n] - v) * t));
  }
  function drawUnrolled() {
    if (!R) return;
    const ratio = window.devicePixelRatio || 1;
    const w = map.clientWidth, h = map.clientHeight;
    if (map.width !== Math.round(w * ratio) || map.height !== Math.round(h * ratio)) {
      map.width = Math.round(w * ratio);
      map.height = Math.round(h * ratio);
    }
    const g = map.getContext("2d");
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, w, h);
    g.font = "11px sans-serif";
    const reached = current >= 0 ? index[current] + 1 : 0;
    let frame = 0;
    while (frame + 1 < R.moves.length && R.moves[frame + 1] <= reached) frame++;
    const n = R.n, m = R.m;
    if (frame !== mapFrame) {  // the frame as an n x m picture, angle 0 at the bottom
      mapImage = document.createElement("canvas");
      mapImage.width = n;
      mapImage.height = m;
      const mc = mapImage.getContext("2d"), pixels = mc.createImageData(n, m);
      for (let k = 0; k < m; k++) {
        for (let i = 0; i < n; i++) {
          const c = depthShade(rotaryDepths[frame * n * m + k * n + i] / 255), p = 4 * ((m - 1 - k) * n + i);
          pixels.data[p] = c[0]; pixels.data[p + 1] = c[1]; pixels.data[p + 2] = c[2]; pixels.data[p + 3] = 255;
        }
      }
      mc.putImageData(pixels, 0, 0);
      mapFrame = frame;
    }
    const left = 52, right = 86, top = 20, bottom = 30;
    const pw = Math.max(w - left - right, 10), ph = Math.max(h - top - bottom, 10);
    const x = (along) => left + (along - R.start) / R.length * pw;
    const y = (angle) => top + ph - angle / 360 * ph;
    g.save();
    g.beginPath();
    g.rect(left, top, pw, ph);
    g.clip();
    g.imageSmoothingEnabled = false;  // blocks past the bar's end or 360 degrees are clipped
    g.drawImage(mapImage, left, top + ph - m * R.blockAngle / 360 * ph, n * R.block / R.length * pw, m * R.blockAngle / 360 * ph);
    g.restore();
    g.strokeStyle = "#888";
    g.lineWidth = 1;
    g.strokeRect(left, top, pw, ph);
    g.fillStyle = "#444";
    g.textAlign = "right";
    for (let a = 0; a <= 360; a += 90) { g.fillText(String(a), left - 4, y(a) + 4); }
    g.textAlign = "center";
    const span = R.length, tick = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000].find((s) => span / s <= 8) || 1000;
    for (let v = Math.ceil(R.start / tick) * tick; v <= R.start + span + 1e-9; v += tick) g.fillText(String(+v.toFixed(3)), x(v), top + ph + 14);
    const along = R.axis === "B" ? "Y" : "X";
    g.fillText(along + " mm along the bar; up: the bar's angle, degrees (at " + R.axis + "0 the tool is at 90)", left + pw / 2, top + ph + 27);
    g.textAlign = "left";
    g.fillText("the bar after move " + R.moves[frame] + " of " + R.moves[R.moves.length - 1] + ": depth below its surface", left, top - 6);
    const bar = [left + pw + 14, top, 12, ph];  // the colour scale: 0 at the top, the deepest at the bottom
    for (let k = 0; k < ph; k++) {
      const c = depthShade(k / ph);
      g.fillStyle = "rgb(" + c.join(",") + ")";
      g.fillRect(bar[0], bar[1] + k, bar[2], 1.5);
    }
    g.fillStyle = "#444";
    g.fillText("0 mm", bar[0] + 16, top + 8);
    g.fillText(R.deepest.toFixed(2) + " mm", bar[0] + 16, top + ph);
    const MARKS = { rapid_into_stock: "#d62728", spindle_off: "#9467bd", holder: "#8c564b", shank: "#ff7f0e" };
    for (const f of R.findings) {
      if (f.move >= reached) continue;
      const colour = MARKS[f.kind] || "#d62728", u = x(f.along);
      g.strokeStyle = colour;
      g.beginPath();
      g.moveTo(u, top);
      g.lineTo(u, top + ph);
      g.stroke();
      const v = f.angle !== null ? y(f.angle) : top + 12;
      g.beginPath();
      g.arc(u, v, 4, 0, 2 * Math.PI);
      g.fillStyle = colour;
      g.fill();
      g.fillText(f.line + " " + f.kind, u + 6, v - 5);
    }
    if (current >= 0 && rotaryTips) {
      const ta = rotaryTips[2 * current], tb = rotaryTips[2 * current + 1];
      if (isFinite(ta) && isFinite(tb)) {
        const u = x(ta), v = y(tb);
        g.beginPath();
        g.moveTo(u - 9, v); g.lineTo(u + 9, v); g.moveTo(u, v - 9); g.lineTo(u, v + 9);
        g.strokeStyle = "#fff";
        g.lineWidth = 4;
        g.stroke();
        g.strokeStyle = "#e02020";
        g.lineWidth = 2;
        g.stroke();
        g.beginPath();
        g.arc(u, v, 5, 0, 2 * Math.PI);
        g.stroke();
      }
    }
  }

  let drawn = 0;
  function draw() {
    projectAll();
    const [w, h] = size();
    ctx.clearRect(0, 0, w, h);
    ctx.lineJoin = "round";
    ctx.font = "11px sans-serif";
    box(D.limits, "#b22222", [6, 3, 1, 3], w, h);
    box(D.part, "#777", [1, 2], w, h);
    drawStock(w, h);
    drawBar(w, h);
    if (otherPoints) {  // the other job of the comparison, thin and light, under this one
      ctx.beginPath();
      for (let i = 0; i < otherFirst.length; i++) {
        for (let p = otherFirst[i]; p <= otherLast[i]; p++) {
          const [x, y] = toScreen(otherProjected[2 * p], otherProjected[2 * p + 1], w, h);
          if (p === otherFirst[i]) ctx.moveTo(x, y); else ctx.lineTo(x, y);
        }
      }
      ctx.strokeStyle = C ? C.oldColor : "#cfcfcf";
      ctx.lineWidth = 1;
      ctx.stroke();
    }
    drawn = 0;
    if (showFuture.checked) {
      ctx.beginPath();
      for (let i = current + 1; i < count; i++) if (showRapids.checked || !isRapid(i)) { tracePolyline(i, w, h); drawn++; }
      ctx.strokeStyle = "#d4d4d4";
      ctx.lineWidth = 1;
      ctx.stroke();
    }
    for (const g of groups) {
      if (g.rapid && !showRapids.checked) continue;
      ctx.beginPath();
      for (const i of g.moves) {
        if (i > current) break;
        tracePolyline(i, w, h);
        drawn++;
      }
      ctx.strokeStyle = g.color;
      ctx.lineWidth = g.rapid ? 1 : C && g.key !== "unchanged" && g.key !== "rapid, unchanged" ? 3 : 1.6;
      ctx.setLineDash(g.rapid ? [4, 3] : []);
      ctx.stroke();
    }
    ctx.setLineDash([]);
    if (current >= 0) {
      ctx.beginPath();
      tracePolyline(current, w, h);
      ctx.strokeStyle = "#ff7f0e";
      ctx.lineWidth = 3.5;
      ctx.stroke();
      const p = last[current];
      const [x, y] = toScreen(projected[2 * p], projected[2 * p + 1], w, h);
      ctx.beginPath();
      ctx.arc(x, y, 5, 0, 2 * Math.PI);
      ctx.fillStyle = "#e02020";
      ctx.fill();
    }
    const [zx, zy] = toScreen(...project(...D.workZero), w, h);
    ctx.beginPath();
    ctx.arc(zx, zy, 6, 0, 2 * Math.PI);
    ctx.moveTo(zx - 9, zy); ctx.lineTo(zx + 9, zy); ctx.moveTo(zx, zy - 9); ctx.lineTo(zx, zy + 9);
    ctx.strokeStyle = "#000";
    ctx.lineWidth = 1.2;
    ctx.stroke();
    triad(w, h);
    drawUnrolled();
    status.dataset.drawn = String(drawn);
  }

  // ---------------------------------------------------------------- readout and listing
  const fmt = (value) => (Math.abs(value) < 5e-5 ? 0 : value).toFixed(3);
  function clock(seconds) {  // 1:02:03.4 or 2:03.4
    const h = Math.floor(seconds / 3600), m = Math.floor(seconds / 60) % 60, s = seconds % 60;
    const ss = (s < 10 ? "0" : "") + s.toFixed(1);
    return h ? h + ":" + String(m).padStart(2, "0") + ":" + ss : m + ":" + ss;
  }

  function readout() {
    const table = document.getElementById("readout");
    table.replaceChildren();
    const row = (name, value, text) => {
      const tr = document.createElement("tr");
      const th = document.createElement("th");
      const td = document.createElement("td");
      th.textContent = name;
      td.textContent = value;
      if (text) td.className = "text";
      tr.append(th, td);
      table.append(tr);
    };
    if (current < 0) { row("move", "none"); return; }
    const i = current, p = last[i];
    const number = index[i] + 1;
    row("move", merged[i] > 1 ? (number - merged[i] + 1) + "\u2013" + number + " of " + D.moves : number + " of " + D.moves, true);
    row("source", D.files[file[i]].replace(/^.*[\\/]/, "") + ":" + line[i], true);
    row("kind", D.kinds[kind[i]] + (merged[i] > 1 ? " (" + merged[i] + " moves merged)" : ""), true);
    row("tool", tool[i] ? "T" + tool[i] : "none", true);
    row("feed", isRapid(i) ? "rapid" : feed[i].toFixed(0) + " mm/min", true);
    row("planned speed", speed[i].toFixed(0) + " mm/min", true);
    row("time", clock(time[i]) + " of " + clock(D.seconds || 0), true);
    ["X", "Y", "Z"].forEach((a, k) => D.xDiameter && k === 0
      ? row("X (diameter)", fmt(2 * points[3 * p]))
      : row(a, fmt(points[3 * p + k])));
    if (abc) ["A", "B", "C"].forEach((a, k) => row(a, fmt(abc[3 * i + k])));
    if (joints) {
      D.jointRows.forEach(([k, name]) => row("joint " + k + " (" + name + ")", fmt(joints[6 * i + k])));
    }
  }

  function listing() {
    const list = document.getElementById("listing");
    list.replaceChildren();
    if (current < 0) return;
    const path = D.files[file[current]];
    const text = D.source[path] || {};
    document.getElementById("listing-title").textContent = "Program: " + path.replace(/^.*[\\/]/, "");
    const here = line[current];
    for (let n = here - 8; n <= here + 8; n++) {
      if (!(String(n) in text)) continue;
      const item = document.createElement("li");
      const number = document.createElement("span");
      number.className = "n";
      number.textContent = String(n);
      item.append(number, text[String(n)]);
      if (n === here) item.className = "current";
      list.append(item);
    }
  }

  function show(i) {
    current = Math.max(Math.min(i, count - 1), count ? 0 : -1);
    slider.value = String(current);
    document.getElementById("counter").textContent = count ? "move " + (index[current] + 1) + " of " + D.moves : "no moves";
    readout();
    listing();
    draw();
  }

  // ---------------------------------------------------------------- player
  // the speed list: "N" plays N moves a second, "xN" N times real time (the planner's move times)
  let playing = false, lastTime = 0, carry = 0, jobClock = 0;
  const playButton = document.getElementById("play");
  function tick(now) {
    if (!playing) return;
    const choice = document.getElementById("speed").value;
    const elapsed = lastTime ? (now - lastTime) / 1000 : 0;
    lastTime = now;
    if (choice.startsWith("x")) {
      jobClock += elapsed * Number(choice.slice(1));
      let next = current;
      while (next < count - 1 && time[next] < jobClock) next++;
      if (next !== current) show(next);
    } else {
      carry += elapsed * Number(choice);
      const step = Math.floor(carry);
      if (step > 0) {
        carry -= step;
        show(current + step);
      }
    }
    if (current >= count - 1) { togglePlay(); return; }
    requestAnimationFrame(tick);
  }
  function togglePlay() {
    playing = !playing && count > 0;
    playButton.textContent = playing ? "pause" : "play";
    if (playing) {
      if (current >= count - 1) show(0);
      lastTime = 0;
      carry = 0;
      jobClock = current > 0 ? time[current - 1] : 0;
      requestAnimationFrame(tick);
    }
  }

  // ---------------------------------------------------------------- input
  let drag = null;
  canvas.addEventListener("contextmenu", (event) => event.preventDefault());
  canvas.addEventListener("pointerdown", (event) => {
    drag = { x: event.clientX, y: event.clientY, pan: event.shiftKey || event.button !== 0 };
    canvas.setPointerCapture(event.pointerId);
    canvas.classList.add("dragging");
  });
  canvas.addEventListener("pointermove", (event) => {
    if (!drag) return;
    const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
    drag.x = event.clientX;
    drag.y = event.clientY;
    if (drag.pan) {
      cam.u -= dx / cam.scale;
      cam.v += dy / cam.scale;
    } else {  // turn about the part's centre: it stays where it is on the screen
      const [pu, pv] = project(...pivot);
      cam.yaw -= dx * 0.01;
      cam.pitch = Math.max(-Math.PI, Math.min(0, cam.pitch - dy * 0.01));
      const [qu, qv] = project(...pivot);
      cam.u += qu - pu;
      cam.v += qv - pv;
      document.querySelectorAll("[data-view]").forEach((b) => b.classList.remove("active"));
    }
    draw();
  });
  const endDrag = () => { drag = null; canvas.classList.remove("dragging"); };
  canvas.addEventListener("pointerup", endDrag);
  canvas.addEventListener("pointercancel", endDrag);
  canvas.addEventListener("wheel", (event) => {
    event.preventDefault();
    const rect = canvas.getBoundingClientRect();
    const mx = event.clientX - rect.left - rect.width / 2, my = event.clientY - rect.top - rect.height / 2;
    const u = cam.u + mx / cam.scale, v = cam.v - my / cam.scale;
    cam.scale *= Math.exp(-event.deltaY * 0.0015);
    cam.u = u - mx / cam.scale;
    cam.v = v + my / cam.scale;
    draw();
  }, { passive: false });

  document.querySelectorAll("[data-view]").forEach((b) => b.addEventListener("click", () => setView(b.dataset.view)));
  document.getElementById("fit").addEventListener("click", () => { fit(); draw(); });
  showRapids.addEventListener("change", draw);
  showFuture.addEventListener("change", draw);
  colorMode.addEventListener("change", () => { buildGroups(); draw(); });
  slider.addEventListener("input", () => show(Number(slider.value)));
  playButton.addEventListener("click", togglePlay);
  document.getElementById("first").addEventListener("click", () => show(0));
  document.getElementById("back").addEventListener("click", () => show(current - 1));
  document.getElementById("forward").addEventListener("click", () => show(current + 1));
  document.getElementById("last-move").addEventListener("click", () => show(count - 1));
  document.addEventListener("keydown", (event) => {
    if (event.target instanceof HTMLInputElement && event.target.type !== "range") return;
    if (event.target instanceof HTMLSelectElement) return;
    const keys = {
      ArrowLeft: () => show(current - 1), ArrowRight: () => show(current + 1), Home: () => show(0),
      End: () => show(count - 1), " ": togglePlay, t: () => setView("top"), f: () => setView("front"),
      s: () => setView("side"), i: () => setView("iso"), l: () => setView("lathe"), 0: () => { fit(); draw(); },
    };
    const action = keys[event.key];
    if (action) { event.preventDefault(); action(); }
  });
  window.addEventListener("resize", draw);

  // ---------------------------------------------------------------- start
  document.getElementById("title").textContent = D.title;
  if (otherData !== null) {
    const toggle = document.createElement("button");
    toggle.type = "button";
    toggle.id = "diff-toggle";
    toggle.textContent = showOld ? "showing OLD \u2192 NEW" : "showing NEW \u2192 OLD";
    toggle.title = "Switch between the two jobs of the comparison (D)";
    const flip = () => {
      const hash = new URLSearchParams(location.hash.slice(1));
      hash.set("job", showOld ? "new" : "old");
      const active = document.querySelector("[data-view].active");
      hash.set("view", active ? active.dataset.view : D.view);
      location.hash = hash.toString();
      location.reload();
    };
    toggle.addEventListener("click", flip);
    document.addEventListener("keydown", (event) => { if (event.key === "d" || event.key === "D") flip(); });
    document.getElementById("toolbar").prepend(toggle);
    document.getElementById("title").textContent = (showOld ? "OLD: " : "NEW: ") + D.title;
  }
  if (C) {  // the list of changes: each a link to its first move (in this job, or where OLD's lies in NEW)
    const mode = document.createElement("option");
    mode.value = "changes";
    mode.textContent = "by change";
    colorMode.prepend(mode);
    colorMode.value = "changes";
    const section = document.createElement("section");
    section.innerHTML = '<h2>Changes</h2><ol id="changes"></ol>';
    const list = section.querySelector("ol");
    if (!C.changes.length) list.append(C.same ? "none: the same" : "none with moves (see ecnc diff)");
    C.changes.forEach((change, n) => {
      const span = showOld ? change.old : change.new || (change.at !== null ? [change.at, change.at] : null);
      const item = document.createElement("li");
      const swatch = document.createElement("span");
      swatch.className = "swatch";
      swatch.style.background = change.color;
      item.append(swatch, change.text);
      item.dataset.change = String(n);
      if (span) {
        item.className = "jump";
        item.title = "show this change";
        item.addEventListener("click", () => {
          let i = 0;
          while (i < count - 1 && index[i] < span[0]) i++;
          show(i);
        });
      }
      list.append(item);
    });
    document.querySelector("aside").prepend(section);
  }
  const notice = document.getElementById("notice");
  const notes = [];
  if (D.error) notes.push("The run stopped: " + D.error);
  if (D.shown < D.moves) {
    notes.push("This job has " + D.moves.toLocaleString("en") + " moves; the page shows " + D.shown.toLocaleString("en") +
      " of them (long runs of feed moves with one tool are thinned). `ecnc view --lines A:B` shows any stretch of the job" +
      " in full; `--max-moves N` raises the budget of " + D.maxMoves.toLocaleString("en") + ".");
  }
  if (notes.length) {
    notice.textContent = notes.join("\n");
    notice.hidden = false;
    notice.classList.toggle("error", Boolean(D.error));
  }
  slider.max = String(Math.max(count - 1, 0));
  buildGroups();
  size();
  // file.html#move=120&view=top opens there (a link to a place in the job)
  const asked = new URLSearchParams(location.hash.slice(1));
  const view = asked.get("view") || D.view;
  setView(VIEWS[view] ? view : "iso");
  const move = Number(asked.get("move"));
  let start = count - 1;
  if (move > 0) {
    start = 0;
    while (start < count - 1 && index[start] + 1 < move) start++;
  }
  show(start);
  status.dataset.ready = "1";
})();
