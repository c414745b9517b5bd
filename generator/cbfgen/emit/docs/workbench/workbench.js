// The workbench page (issue 34, point 3). It runs cbf-c.wasm (the C engine, c-wasm binding) as a WASI
// command over an in-memory file system and shows what it prints: `cbf-c validate` (verdict, findings)
// and `cbf-c dump` (the records); CUT text (`cbf-c sniff`) is first encoded by the engine (`cbf-c encode`).
// Nothing here checks or reads a file's format: every finding is the engine's. What the
// page knows of the format (byte layouts, profiles, each check's place in the document) is the spec's,
// as data (#cbf-data, written by cbfgen.emit.docs.workbench).
'use strict';

const DATA = JSON.parse(document.getElementById('cbf-data').textContent);
const PAGE_SIZE = 100;

// -- a WASI preview1 command in the page -----------------------------------------------------------
// The imports cbf-c.wasm uses (WebAssembly.Module.imports), over files held in memory: fd 3 is the
// preopened directory "/", where the page's files are; stdout and stderr are collected as text.
const ERRNO = { SUCCESS: 0, BADF: 8, INVAL: 28, NOENT: 44, NOTSUP: 58 };

class Exit {
  constructor(code) { this.code = code; }
}

let compiled = null;

function wasmModule() {
  if (compiled === null) {
    const bin = atob(CBF_WASM_BASE64);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i += 1) bytes[i] = bin.charCodeAt(i);
    compiled = new WebAssembly.Module(bytes);
  }
  return compiled;
}

function runCommand(args, files, binary = false) {
  const enc = new TextEncoder();
  const out = [[], [], []];
  const open = new Map(); // fd -> { data, pos }
  let nextFd = 4;
  let memory = null;
  const view = () => new DataView(memory.buffer);
  const bytes = () => new Uint8Array(memory.buffer);
  const argv = args.map((a) => enc.encode(`${a}\0`));
  const iovs = (ptr, n) => {
    const v = view();
    const list = [];
    for (let i = 0; i < n; i += 1) list.push([v.getUint32(ptr + 8 * i, true), v.getUint32(ptr + 8 * i + 4, true)]);
    return list;
  };
  const filestat = (ptr, type, size) => { // WASI filestat: dev, ino, filetype, nlink, size, 3 times
    const v = view();
    for (let k = 0; k < 64; k += 8) v.setBigUint64(ptr + k, 0n, true);
    v.setUint8(ptr + 16, type);
    v.setBigUint64(ptr + 24, 1n, true);
    v.setBigUint64(ptr + 32, BigInt(size), true);
  };
  const imports = {
    args_sizes_get(countPtr, sizePtr) {
      view().setUint32(countPtr, argv.length, true);
      view().setUint32(sizePtr, argv.reduce((n, a) => n + a.length, 0), true);
      return ERRNO.SUCCESS;
    },
    args_get(argvPtr, bufPtr) {
      let at = bufPtr;
      argv.forEach((a, i) => {
        view().setUint32(argvPtr + 4 * i, at, true);
        bytes().set(a, at);
        at += a.length;
      });
      return ERRNO.SUCCESS;
    },
    fd_prestat_get(fd, ptr) {
      if (fd !== 3) return ERRNO.BADF;
      view().setUint32(ptr, 0, true); // a directory
      view().setUint32(ptr + 4, 1, true); // its name: "/"
      return ERRNO.SUCCESS;
    },
    fd_prestat_dir_name(fd, ptr, len) {
      if (fd !== 3 || len < 1) return ERRNO.BADF;
      bytes()[ptr] = 0x2f;
      return ERRNO.SUCCESS;
    },
    fd_fdstat_get(fd, ptr) {
      const type = fd <= 2 ? 2 : fd === 3 ? 3 : open.has(fd) ? 4 : -1; // char device, directory, file
      if (type < 0) return ERRNO.BADF;
      const v = view();
      v.setUint8(ptr, type);
      v.setUint16(ptr + 2, 0, true);
      v.setBigUint64(ptr + 8, 0xffffffffffffffffn, true);
      v.setBigUint64(ptr + 16, 0xffffffffffffffffn, true);
      return ERRNO.SUCCESS;
    },
    fd_fdstat_set_flags() { return ERRNO.SUCCESS; },
    // The engine opens regular files only (tools/files.c: stat, then fstat): a chosen file is one.
    fd_filestat_get(fd, ptr) {
      const type = fd <= 2 ? 2 : fd === 3 ? 3 : open.has(fd) ? 4 : -1;
      if (type < 0) return ERRNO.BADF;
      filestat(ptr, type, type === 4 ? open.get(fd).data.length : 0);
      return ERRNO.SUCCESS;
    },
    path_filestat_get(dirFd, flags, pathPtr, pathLen, ptr) {
      if (dirFd !== 3) return ERRNO.BADF;
      const name = new TextDecoder().decode(bytes().slice(pathPtr, pathPtr + pathLen));
      if (!files.has(name)) return ERRNO.NOENT;
      filestat(ptr, 4, files.get(name).length);
      return ERRNO.SUCCESS;
    },
    path_open(dirFd, dirFlags, pathPtr, pathLen, oflags, rightsBase, rightsInherit, fdFlags, fdPtr) {
      if (dirFd !== 3) return ERRNO.BADF;
      const name = new TextDecoder().decode(bytes().slice(pathPtr, pathPtr + pathLen));
      if (!files.has(name) || (oflags & 2) !== 0) return ERRNO.NOENT; // no such file; O_DIRECTORY
      const fd = nextFd;
      nextFd += 1;
      open.set(fd, { data: files.get(name), pos: 0 });
      view().setUint32(fdPtr, fd, true);
      return ERRNO.SUCCESS;
    },
    fd_read(fd, iovPtr, iovCount, nreadPtr) {
      let n = 0;
      const f = open.get(fd);
      if (f !== undefined) {
        for (const [buf, len] of iovs(iovPtr, iovCount)) {
          const chunk = f.data.subarray(f.pos, Math.min(f.pos + len, f.data.length));
          bytes().set(chunk, buf);
          f.pos += chunk.length;
          n += chunk.length;
          if (chunk.length < len) break;
        }
      } else if (fd !== 0) {
        return ERRNO.BADF;
      }
      view().setUint32(nreadPtr, n, true);
      return ERRNO.SUCCESS;
    },
    fd_seek(fd, offset, whence, newPtr) {
      const f = open.get(fd);
      if (f === undefined) return ERRNO.BADF;
      const base = whence === 0 ? 0 : whence === 1 ? f.pos : f.data.length;
      const pos = base + Number(offset);
      if (pos < 0) return ERRNO.INVAL;
      f.pos = pos;
      view().setBigUint64(newPtr, BigInt(pos), true);
      return ERRNO.SUCCESS;
    },
    fd_write(fd, iovPtr, iovCount, nwrittenPtr) {
      if (fd !== 1 && fd !== 2) return ERRNO.BADF;
      let n = 0;
      for (const [buf, len] of iovs(iovPtr, iovCount)) {
        out[fd].push(bytes().slice(buf, buf + len));
        n += len;
      }
      view().setUint32(nwrittenPtr, n, true);
      return ERRNO.SUCCESS;
    },
    fd_close(fd) {
      return open.delete(fd) ? ERRNO.SUCCESS : ERRNO.BADF;
    },
    proc_exit(code) { throw new Exit(code); },
  };
  const instance = new WebAssembly.Instance(wasmModule(), { wasi_snapshot_preview1: imports });
  memory = instance.exports.memory;
  let status = 0;
  try {
    instance.exports._start();
  } catch (e) {
    if (!(e instanceof Exit)) throw e;
    status = e.code;
  }
  const text = (chunks) => {
    const all = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
    let at = 0;
    for (const c of chunks) { all.set(c, at); at += c.length; }
    return new TextDecoder().decode(all);
  };
  if (binary) { // the standard output as bytes (cbf-c encode's CBF), not as text
    const raw = new Uint8Array(out[1].reduce((n, c) => n + c.length, 0));
    let at = 0;
    for (const c of out[1]) { raw.set(c, at); at += c.length; }
    return { status, stdout: '', stderr: text(out[2]), bytes: raw };
  }
  return { status, stdout: text(out[1]), stderr: text(out[2]) };
}

// -- reading what cbf-c prints ---------------------------------------------------------------------
// A finding line of `cbf-c validate`: FILE:OFFSET: SEVERITY CHECK (WHERE): MESSAGE (the tool's own
// format; a line that is not one is shown as it is).
const FINDING = /^(.*):(\d+): (error|warning) (\S+) \(([^)]*)\): (.*)$/;

function parseFindings(text) {
  return text.split('\n').filter((l) => l !== '').map((line) => {
    const m = FINDING.exec(line);
    if (m === null) return { line };
    const rec = /^record (\d+)$/.exec(m[5]);
    return { line, offset: Number(m[2]), severity: m[3], check: m[4], where: m[5],
      record: rec === null ? null : Number(rec[1]), message: m[6] };
  });
}

// A record line of `cbf-c dump`: INDEX @OFFSET NAME head fields | arguments
const RECORD = /^(\d+) @(\d+) (\S+) (.*?)(?: \| (.*))?$/;

function parseDump(text) {
  const lines = text.split('\n');
  const header = /^header version (\S+)/.exec(lines[0] || '');
  const records = [];
  for (const line of lines.slice(1)) {
    const m = RECORD.exec(line);
    if (m === null) continue;
    const size = /\barg_size=(\d+)/.exec(m[4]);
    records.push({ index: Number(m[1]), offset: Number(m[2]), name: m[3], head: m[4], args: m[5] || '',
      argSize: size === null ? 0 : Number(size[1]) });
  }
  return { version: header === null ? null : header[1], headerLine: lines[0] || '', records };
}

// -- the spec's byte layouts -------------------------------------------------------------------------
const L = DATA.layouts;

function headerFields(version) {
  const v = L.versions.find((x) => x.id === version);
  const h = v === undefined ? L.headers[L.versions[L.versions.length - 1].header] : L.headers[v.header];
  return h.fields.map((f) => ({ name: f.name, offset: f.offset, size: f.size, doc: f.doc }));
}

function recordFields(rec, version) {
  const head = L.record_head.fields.map((f) => ({ name: f.name, offset: rec.offset + f.offset, size: f.size,
    doc: f.doc }));
  const cmd = L.commands.find((c) => c.name === rec.name);
  const lay = cmd === undefined ? undefined
    : cmd.layouts.find((l) => l.versions.includes(version) && l.size === rec.argSize)
      || cmd.layouts.find((l) => l.size === rec.argSize);
  const base = rec.offset + L.record_head.size;
  const args = lay === undefined ? [{ name: 'arguments', offset: base, size: rec.argSize, doc: '' }]
    : lay.args.map((a) => ({ name: a.name, offset: base + a.offset, size: a.size, doc: a.doc }));
  return head.concat(args);
}

// -- the toolpath ---------------------------------------------------------------------------------------
// Each motion record's path as the engine draws it (`cbf-c dump --path`: cbf_motion_path, the engine's
// own geometry: a circle, helix or arc turned as its checks turn it), one line a record: INDEX x,y,z ...
// Cutting or moving: the state the spec's `sets: {cutting: ...}` commands leave before the record.
const SVG = 'http://www.w3.org/2000/svg';

function parsePath(text) {
  const out = new Map();
  for (const line of text.split('\n')) {
    const parts = line.split(' ');
    if (parts.length < 2 || !/^\d+$/.test(parts[0])) continue;
    const pts = parts.slice(1).map((p) => p.split(',').map(Number));
    if (pts.every((p) => p.length === 3 && p.every(Number.isFinite))) out.set(Number(parts[0]), pts);
  }
  return out;
}

function segments(records, paths) {
  const out = [];
  let cutting = false;
  for (const r of records) {
    if (Object.prototype.hasOwnProperty.call(DATA.cutting, r.name)) cutting = DATA.cutting[r.name];
    const pts = paths.get(r.index);
    if (pts !== undefined) out.push({ record: r.index, cutting, pts });
  }
  return out;
}

function drawView(svg, segs, axes) {
  svg.replaceChildren();
  const xs = [];
  const ys = [];
  for (const s of segs) for (const p of s.pts) { xs.push(p[axes[0]]); ys.push(-p[axes[1]]); }
  if (xs.length === 0) {
    svg.setAttribute('viewBox', '0 0 100 100');
    const t = document.createElementNS(SVG, 'text');
    t.setAttribute('x', '6');
    t.setAttribute('y', '50');
    t.textContent = 'no motion record';
    svg.append(t);
    return [];
  }
  // bounds by a loop: a spread of 100,000 arguments can overflow the stack
  let [x0, x1, y0, y1] = [xs[0], xs[0], ys[0], ys[0]];
  for (let i = 1; i < xs.length; i += 1) {
    x0 = Math.min(x0, xs[i]); x1 = Math.max(x1, xs[i]); y0 = Math.min(y0, ys[i]); y1 = Math.max(y1, ys[i]);
  }
  // the view as wide as the path, at least a quarter as high (a flat side view stays a strip)
  const w = Math.max(x1 - x0, y1 - y0, 1e-6);
  const h = Math.max(y1 - y0, w / 4);
  const pad = w * 0.06;
  svg.setAttribute('viewBox', `${x0 - pad} ${(y0 + y1) / 2 - h / 2 - pad} ${Math.max(x1 - x0, w) + 2 * pad} ${h + 2 * pad}`);
  const drawn = [];
  for (const s of segs) {
    const d = s.pts.map((p, i) => `${i === 0 ? 'M' : 'L'}${p[axes[0]]} ${-p[axes[1]]}`).join(' ');
    const path = document.createElementNS(SVG, 'path');
    path.setAttribute('d', s.pts.length === 1 ? `${d} l0 0` : d);
    path.setAttribute('class', s.cutting ? 'wb-cut' : 'wb-move');
    path.dataset.record = String(s.record);
    if (state.byRecord.has(s.record)) path.classList.add('wb-has-finding');
    if (axes[1] === 1) { // the top view's segments are the toolpath's buttons (Tab stops: tabStops)
      path.setAttribute('role', 'button');
      path.setAttribute('aria-label', `record ${s.record}, ${s.cutting ? 'cutting' : 'moving'}`);
    }
    svg.append(path);
    drawn.push(path);
  }
  return drawn;
}

function showPath(paths) {
  const segs = segments(state.dump.records, paths);
  state.segs = new Map();
  state.tabbable = [];
  for (const [id, axes] of [['path-top', [0, 1]], ['path-side', [0, 2]]]) {
    for (const p of drawView($(id), segs, axes)) {
      const n = Number(p.dataset.record);
      if (!state.segs.has(n)) state.segs.set(n, []);
      state.segs.get(n).push(p);
    }
  }
  view3d.load(segs);
}

// The top view's segments are Tab stops a page at a time, as the records are: those of the records on
// the records' current page (65,535 segments in the tab order made the rest of the page unreachable).
function tabStops() {
  for (const p of state.tabbable) p.removeAttribute('tabindex');
  state.tabbable = [];
  for (const r of state.dump.records.slice(state.page * PAGE_SIZE, (state.page + 1) * PAGE_SIZE)) {
    for (const p of state.segs.get(r.index) || []) {
      if (p.ownerSVGElement.id !== 'path-top') continue;
      p.setAttribute('tabindex', '0');
      state.tabbable.push(p);
    }
  }
}

function markSegment(record) {
  for (const p of document.querySelectorAll('.wb-path path.wb-selected')) p.classList.remove('wb-selected');
  for (const p of state.segs.get(record) || []) {
    p.classList.add('wb-selected');
    p.parentNode.append(p); // drawn on top of its neighbours
  }
  view3d.select(record);
}

// -- the 3D view: the same segments on a canvas, an orthographic view turned about the path's centre ----
// Drag or the arrow keys turn it, the wheel or + and - zoom, 0 resets; a click, or [ and ] (the motion
// record before or after), selects a segment's record, as in the other views.
const view3d = (() => {
  const HOME = { yaw: -0.6, pitch: 0.55, zoom: 1 };
  const STEP = Math.PI / 12;
  let segs = [];
  let centre = [0, 0, 0];
  let radius = 1;
  let selected;
  let v = { ...HOME };
  const canvas = () => $('path-3d');

  function project(p, w, h) {
    const x = p[0] - centre[0];
    const y = p[1] - centre[1];
    const z = p[2] - centre[2];
    const cy = Math.cos(v.yaw);
    const sy = Math.sin(v.yaw);
    const xr = x * cy - y * sy;
    const yr = x * sy + y * cy;
    const s = (v.zoom * 0.45 * Math.min(w, h)) / radius;
    return [w / 2 + s * xr, h / 2 - s * (yr * Math.sin(v.pitch) + z * Math.cos(v.pitch))];
  }

  // a segment's points into the current path (one stroke a style: 65,535 strokes took half a second)
  function trace(ctx, s, w, h) {
    s.pts.forEach((p, i) => {
      const [px, py] = project(p, w, h);
      if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    });
  }

  const STYLES = { finding: ['#cf222e', 2, []], cut: ['#0969da', 2, []], move: ['#8c959f', 1.5, [4, 3]],
    selected: ['#bf8700', 5, []] };

  function strokeAll(ctx, list, name, w, h) {
    if (list.length === 0) return;
    const [colour, width, dash] = STYLES[name];
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.setLineDash(dash);
    ctx.beginPath();
    for (const s of list) trace(ctx, s, w, h);
    ctx.stroke();
  }

  function draw() {
    const c = canvas();
    const w = c.clientWidth;
    const h = c.clientHeight;
    const dpr = window.devicePixelRatio || 1;
    c.width = Math.round(w * dpr);
    c.height = Math.round(h * dpr);
    const ctx = c.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, w, h);
    ctx.lineCap = 'round';
    ctx.lineJoin = 'round';
    // the axes, from the path's centre: x red, y green, z blue
    const o = project(centre, w, h);
    [['x', '#cf222e'], ['y', '#1a7f37'], ['z', '#0550ae']].forEach(([name, colour], k) => {
      const tip = centre.slice();
      tip[k] += radius * 0.3;
      const t = project(tip, w, h);
      ctx.strokeStyle = colour;
      ctx.lineWidth = 1;
      ctx.setLineDash([]);
      ctx.beginPath(); ctx.moveTo(o[0], o[1]); ctx.lineTo(t[0], t[1]); ctx.stroke();
      ctx.fillStyle = colour;
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillText(name, t[0] + 3, t[1] - 3);
    });
    const groups = { move: [], cut: [], finding: [], selected: [] };
    for (const s of segs) groups[state.byRecord.has(s.record) ? 'finding' : s.cutting ? 'cut' : 'move'].push(s);
    groups.selected = segs.filter((s) => s.record === selected);
    for (const name of ['move', 'cut', 'finding', 'selected']) strokeAll(ctx, groups[name], name, w, h);
    if (segs.length === 0) {
      ctx.fillStyle = '#57606a';
      ctx.font = '13px system-ui, sans-serif';
      ctx.fillText('no motion record', 10, h / 2);
    }
    Object.assign(c.dataset, { yaw: v.yaw.toFixed(4), pitch: v.pitch.toFixed(4), zoom: v.zoom.toFixed(4),
      selected: selected === undefined ? '' : String(selected), segments: String(segs.length) });
  }

  function load(list) {
    segs = list;
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (const s of segs) {
      for (const p of s.pts) for (let k = 0; k < 3; k += 1) { lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]); }
    }
    centre = segs.length === 0 ? [0, 0, 0] : lo.map((x, k) => (x + hi[k]) / 2);
    radius = segs.length === 0 ? 1 : Math.max(Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2, 1e-6);
    selected = undefined;
    v = { ...HOME };
    draw();
  }

  function select(record) { selected = record; draw(); }

  // the segment drawn nearest a point of the canvas (CSS pixels), within 10 px
  function pick(x, y) {
    const c = canvas();
    let best = null;
    let dist = 10;
    for (const s of segs) {
      let a = project(s.pts[0], c.clientWidth, c.clientHeight);
      for (let i = s.pts.length === 1 ? 0 : 1; i < s.pts.length; i += 1) {
        const b = project(s.pts[i], c.clientWidth, c.clientHeight);
        const dx = b[0] - a[0];
        const dy = b[1] - a[1];
        const len2 = dx * dx + dy * dy;
        const t = len2 === 0 ? 0 : Math.max(0, Math.min(1, ((x - a[0]) * dx + (y - a[1]) * dy) / len2));
        const d = Math.hypot(x - a[0] - t * dx, y - a[1] - t * dy);
        if (d < dist) { dist = d; best = s.record; }
        a = b;
      }
    }
    return best;
  }

  // where a record's segment is drawn (its middle point, CSS pixels from the canvas' corner)
  function where(record) {
    const s = segs.find((x) => x.record === record);
    if (s === undefined) return null;
    const c = canvas();
    const n = s.pts.length;
    const a = project(s.pts[Math.floor((n - 1) / 2)], c.clientWidth, c.clientHeight);
    const b = project(s.pts[Math.floor(n / 2)], c.clientWidth, c.clientHeight);
    return [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
  }

  function step(by) {
    if (segs.length === 0) return;
    const at = segs.findIndex((s) => s.record === selected);
    const next = at < 0 ? (by > 0 ? 0 : segs.length - 1) : Math.max(0, Math.min(segs.length - 1, at + by));
    select3d(segs[next].record);
  }

  let select3d = () => {};
  const KEYS = {
    ArrowLeft: () => { v.yaw -= STEP; }, ArrowRight: () => { v.yaw += STEP; },
    ArrowUp: () => { v.pitch = Math.min(Math.PI / 2, v.pitch + STEP); },
    ArrowDown: () => { v.pitch = Math.max(-Math.PI / 2, v.pitch - STEP); },
    '+': () => { v.zoom = Math.min(50, v.zoom * 1.25); }, '=': () => { v.zoom = Math.min(50, v.zoom * 1.25); },
    '-': () => { v.zoom = Math.max(0.2, v.zoom / 1.25); }, 0: () => { v = { ...HOME }; },
    '[': () => step(-1), ']': () => step(1),
  };

  function setup(onSelect) {
    select3d = onSelect;
    const c = canvas();
    c.addEventListener('keydown', (e) => {
      const act = KEYS[e.key];
      if (act === undefined) return;
      e.preventDefault();
      act();
      draw();
    });
    let drag = null;
    c.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY, moved: false }; c.setPointerCapture(e.pointerId); });
    c.addEventListener('pointermove', (e) => {
      if (drag === null) return;
      const dx = e.clientX - drag.x;
      const dy = e.clientY - drag.y;
      if (!drag.moved && Math.hypot(dx, dy) < 3) return;
      drag.moved = true;
      v.yaw += dx * 0.01;
      v.pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, v.pitch + dy * 0.01));
      drag.x = e.clientX;
      drag.y = e.clientY;
      draw();
    });
    c.addEventListener('pointerup', (e) => {
      const click = drag !== null && !drag.moved;
      drag = null;
      if (!click) return;
      const r = c.getBoundingClientRect();
      const rec = pick(e.clientX - r.left, e.clientY - r.top);
      if (rec !== null) select3d(rec);
    });
    c.addEventListener('wheel', (e) => {
      e.preventDefault();
      v.zoom = Math.max(0.2, Math.min(50, v.zoom * (e.deltaY < 0 ? 1.15 : 1 / 1.15)));
      draw();
    }, { passive: false });
    window.addEventListener('resize', draw);
  }

  return { load, select, setup, where, pick, draw };
})();

// -- the page ------------------------------------------------------------------------------------------
const $ = (id) => document.getElementById(id);
const state = { name: null, data: null, findings: [], dump: null, page: 0, selected: null, byRecord: new Map(),
  segs: new Map(), tabbable: [] };

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'class') e.className = v; else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

async function readInput(input) {
  const f = input.files && input.files[0];
  return f === undefined ? null : { name: f.name, data: new Uint8Array(await f.arrayBuffer()) };
}

// The page's files live in "/" under their own names, so cbf-c prints the name the reader chose.
function safeName(name, fallback) {
  return name && !name.includes('/') && name !== '.' && name !== '..' ? name : fallback;
}

// A newer request (another file, profile or option file) supersedes one still reading its files: each
// takes its number when the reader acts, before any file is read, and only the newest one runs.
let generation = 0;

async function check(readFile) {
  generation += 1;
  const mine = generation;
  document.body.dataset.generation = String(mine);
  const profile = $('profile').value;
  const file = await readFile();
  const options = [];
  for (const id of ['cutters', 'machine']) options.push(await readInput($(id)));
  if (file === null) return;
  if (mine !== generation) return;
  const chosen = safeName(file.name, 'input.cbf');
  state.name = chosen;
  state.data = file.data;
  const files = new Map([[state.name, file.data]]);
  // CUT text (the engine's rule, cbf-c sniff: no magic number of the header right, or shorter than the
  // header, and the first 256 bytes text) is encoded by the engine (cbf-c encode) and shown as that CBF.
  const cut = runCommand(['cbf-c', 'sniff', chosen], files).stdout.trim() === 'cut';
  showCut(null);
  if (cut) {
    const enc = runCommand(['cbf-c', 'encode', '--profile', profile, chosen, '-o', '-'], files, true);
    if (enc.status !== 0) {
      showCutError(enc, chosen, profile, mine);
      return;
    }
    state.name = safeName(`${chosen.replace(/\.cut$/i, '')}.cbf`, 'input.cbf');
    if (state.name === chosen) state.name = `encoded-${chosen}`;
    state.data = enc.bytes;
    files.set(state.name, enc.bytes);
    showCut(chosen, state.name, enc.bytes);
  }
  const args = ['cbf-c', 'validate', '--max-findings', '0', '--profile', profile];
  const flags = [['--cutters', 'cutters.txt'], ['--machine', 'machine.json']];
  for (const [i, [flag, fallback]] of flags.entries()) {
    const opt = options[i];
    if (opt !== null) {
      const n = safeName(opt.name, fallback) === state.name ? `option-${fallback}` : safeName(opt.name, fallback);
      files.set(n, opt.data);
      args.push(flag, n);
    }
  }
  args.push(state.name);
  const v = runCommand(args, files);
  $('raw').textContent = v.stdout + v.stderr;
  state.findings = parseFindings(v.stdout);
  const d = runCommand(['cbf-c', 'dump', state.name], files);
  state.dump = d.status === 0 ? parseDump(d.stdout) : { version: null, headerLine: '', records: [] };
  const drawn = d.status === 0 ? runCommand(['cbf-c', 'dump', '--path', state.name], files) : null;
  const paths = drawn !== null && drawn.status === 0 ? parsePath(drawn.stdout) : new Map();
  state.byRecord = new Map();
  state.findings.forEach((f, i) => { if (f.record != null) state.byRecord.set(f.record, i); });
  state.selected = null;
  state.page = 0;
  showVerdict(v);
  showFindings();
  showHex(null);
  showPath(paths);
  showRecords();
  Object.assign(document.body.dataset, { done: String(mine), file: chosen, profile, shown: state.name });
}

// The note over a CUT file's results: what it encoded to, and the CBF to download (a blob URL: no network).
let cutUrl = null;
function showCut(source, name, bytes) {
  if (cutUrl !== null) URL.revokeObjectURL(cutUrl);
  cutUrl = null;
  const note = $('cut-note');
  note.hidden = source === null;
  if (source === null) return;
  cutUrl = URL.createObjectURL(new Blob([bytes], { type: 'application/octet-stream' }));
  $('cut-text').textContent = `${source}: CUT text, shown as the CBF it encodes to (${bytes.length} bytes). `;
  const a = $('cut-download');
  a.href = cutUrl;
  a.download = name;
  a.textContent = `Download ${name}`;
}

// A CUT file the engine does not encode: its one line (cbf-c encode's), and nothing else to show.
function showCutError(enc, chosen, profile, mine) {
  state.findings = [];
  state.dump = { version: null, headerLine: '', records: [] };
  state.data = new Uint8Array(0);
  state.byRecord = new Map();
  state.selected = null;
  state.page = 0;
  $('raw').textContent = enc.stderr;
  showVerdict(enc);
  $('verdict').textContent = `CUT text that does not encode: ${enc.stderr.trim()}`;
  showFindings();
  $('hex').replaceChildren();
  $('legend').replaceChildren();
  $('hex-title').textContent = '';
  showPath(new Map());
  showRecords();
  Object.assign(document.body.dataset, { done: String(mine), file: chosen, profile, shown: '' });
}

function showVerdict(v) {
  const summary = state.findings.filter((f) => f.check === undefined).map((f) => f.line);
  const text = summary.length > 0 ? summary[summary.length - 1] : v.stderr.trim() || `exit status ${v.status}`;
  $('verdict').textContent = text;
  $('verdict').className = `wb-verdict ${v.status === 0 ? 'wb-ok' : 'wb-fail'}`;
  $('verdict').dataset.status = String(v.status);
}

function showFindings() {
  const ol = $('findings');
  ol.replaceChildren();
  state.findings.forEach((f, i) => {
    if (f.check === undefined) return;
    const k = DATA.checks[f.check];
    const link = k === undefined ? document.createTextNode(f.check)
      : el('a', { href: k.href, title: k.text || '' }, f.check);
    const where = f.record === null ? `(${f.where})` : `(record ${f.record})`;
    const b = el('button', { type: 'button', 'data-finding': String(i), onclick: () => select({ finding: i }) },
      el('span', { class: `wb-${f.severity}` }, f.severity), ` ${where} at byte ${f.offset}: ${f.message}`);
    ol.append(el('li', {}, link, ' ', b));
  });
}

function pageCount() {
  return Math.max(1, Math.ceil(state.dump.records.length / PAGE_SIZE));
}

function showRecords() {
  const tbody = $('records').querySelector('tbody');
  tbody.replaceChildren();
  const recs = state.dump.records.slice(state.page * PAGE_SIZE, (state.page + 1) * PAGE_SIZE);
  for (const r of recs) {
    const tr = el('tr', { tabindex: '0', 'data-record': String(r.index), onclick: () => select({ record: r.index }),
      onkeydown: (e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); select({ record: r.index }); } } },
    el('td', {}, String(r.index)), el('td', {}, String(r.offset)), el('td', {}, r.name), el('td', {}, r.args));
    if (state.byRecord.has(r.index)) tr.classList.add('wb-has-finding');
    if (state.selected !== null && state.selected.record === r.index) tr.classList.add('wb-selected');
    tbody.append(tr);
  }
  $('page-info').textContent = `page ${state.page + 1} of ${pageCount()} (${state.dump.records.length} records)`;
  $('prev').disabled = state.page === 0;
  $('next').disabled = state.page + 1 >= pageCount();
  tabStops();
}

function hexByte(b) {
  return b.toString(16).padStart(2, '0');
}

// The bytes of the header (no record selected) or of one record, each field in its own colour and
// named in the legend; the byte a finding names is marked.
// Sixteen bytes a row, or eight where sixteen would not fit the box (the site's 390 px rule: the
// byte rows scrolled 140 px sideways at 390 px).
function showHex(rec, hit) {
  state.hexShown = [rec, hit];
  drawHex(rec, hit, 16);
  const box = $('hex').parentNode;
  if (box.scrollWidth > box.clientWidth) drawHex(rec, hit, 8);
}

function drawHex(rec, hit, perRow) {
  const fields = rec === null ? headerFields(state.dump.version) : recordFields(rec, state.dump.version);
  const start = fields.length > 0 ? Math.min(...fields.map((f) => f.offset)) : 0;
  const end = Math.min(state.data.length, fields.length > 0 ? Math.max(...fields.map((f) => f.offset + f.size)) : 0);
  const owner = new Map();
  fields.forEach((f, i) => { for (let o = f.offset; o < f.offset + f.size; o += 1) owner.set(o, i); });
  const hex = $('hex');
  hex.replaceChildren();
  for (let row = start - (start % perRow); row < end; row += perRow) {
    const line = el('span', { class: 'wb-row' }, el('span', { class: 'wb-off' }, `${row.toString(16).padStart(8, '0')}  `));
    for (let o = row; o < row + perRow; o += 1) {
      if (o < start || o >= end) { line.append('   '); continue; }
      const i = owner.get(o);
      const cls = i === undefined ? 'wb-b' : `wb-b wb-f${i % 6}`;
      const span = el('span', { class: cls + (o === hit ? ' wb-hit' : ''), 'data-offset': String(o),
        title: i === undefined ? `byte ${o}` : `${fields[i].name} (byte ${o})` }, hexByte(state.data[o]));
      line.append(span, ' ');
    }
    hex.append(line);
  }
  $('hex-title').textContent = rec === null ? `header, bytes ${start} to ${end - 1}`
    : `record ${rec.index} (${rec.name}), bytes ${start} to ${end - 1}`;
  const legend = $('legend');
  legend.replaceChildren();
  fields.forEach((f, i) => legend.append(el('li', {}, el('button', { type: 'button', class: `wb-f${i % 6}`,
    title: f.doc || '', onclick: () => markField(f) }, `${f.name} @${f.offset} (${f.size} B)`))));
}

function markField(f) {
  for (const s of $('hex').querySelectorAll('.wb-b')) {
    const o = Number(s.dataset.offset);
    s.classList.toggle('wb-selected', o >= f.offset && o < f.offset + f.size);
  }
}

// One selection across the findings, the records and the bytes.
function select(sel) {
  let record = sel.record;
  let hit;
  if (sel.finding !== undefined) {
    const f = state.findings[sel.finding];
    record = f.record === null ? undefined : f.record;
    hit = f.offset;
  } else if (state.byRecord.has(record)) {
    hit = state.findings[state.byRecord.get(record)].offset;
  }
  const finding = sel.finding !== undefined ? sel.finding : state.byRecord.get(record);
  state.selected = { record, finding };
  for (const b of $('findings').querySelectorAll('button')) {
    b.classList.toggle('wb-selected', Number(b.dataset.finding) === finding);
  }
  const rec = record === undefined ? null : state.dump.records.find((r) => r.index === record) || null;
  if (rec !== null) state.page = Math.floor(state.dump.records.indexOf(rec) / PAGE_SIZE);
  showRecords();
  showHex(rec, hit);
  markSegment(record);
}

function setup() {
  for (const p of DATA.profiles) $('profile').append(el('option', { value: p.id, title: p.doc }, p.id));
  const chosen = () => readInput($('file'));
  let source = chosen; // the file shown: the one chosen, or the one dropped since (a profile change shows it again)
  $('file').addEventListener('change', () => { source = chosen; check(chosen); });
  $('profile').addEventListener('change', () => check(source));
  for (const id of ['cutters', 'machine']) $(id).addEventListener('change', () => check(source));
  const drop = $('drop');
  drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('wb-over'); });
  drop.addEventListener('dragleave', () => drop.classList.remove('wb-over'));
  drop.addEventListener('drop', async (e) => {
    e.preventDefault();
    drop.classList.remove('wb-over');
    const f = e.dataTransfer.files[0];
    if (f === undefined) return;
    $('file').value = ''; // the chooser no longer names the file shown
    source = async () => ({ name: f.name, data: new Uint8Array(await f.arrayBuffer()) });
    await check(source);
  });
  drop.addEventListener('keydown', (e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); $('file').click(); } });
  for (const id of ['path-top', 'path-side']) {
    const pick = (e) => {
      const p = e.target.closest && e.target.closest('path[data-record]');
      if (p) select({ record: Number(p.dataset.record) });
    };
    $(id).addEventListener('click', pick);
    $(id).addEventListener('keydown', (e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); pick(e); } });
  }
  view3d.setup((record) => select({ record }));
  window.addEventListener('resize', () => { if (state.hexShown !== undefined) showHex(...state.hexShown); });
  $('prev').addEventListener('click', () => { state.page = Math.max(0, state.page - 1); showRecords(); });
  $('next').addEventListener('click', () => { state.page = Math.min(pageCount() - 1, state.page + 1); showRecords(); });
  $('goto').addEventListener('change', () => {
    const n = Number($('goto').value);
    if (state.dump !== null && Number.isInteger(n)) select({ record: n });
  });
}

setup();
// For the browser test (tests/workbench/drive.mjs): where the 3D view draws a record's segment, and
// which record a point of it picks.
window.cbfWorkbench = { where3d: (record) => view3d.where(record), pick3d: (x, y) => view3d.pick(x, y) };
