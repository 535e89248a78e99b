// SPDX-License-Identifier: MIT
// iskra in a web page: loads iskra.wasm (web/iskra_web.c, built by
// `make web`), passes the page's pointer and keyboard events in, and shows
// the window's canvas (the scene and the simulator's panel, drawn by
// iskra itself) in an HTML canvas scaled by whole numbers.  Nothing is
// fetched but iskra.wasm, from beside this file.
//
// The page's own controls: the scene picker, the editor (its text is
// applied on demand: a mistake shows FILE:LINE and the last good scene
// keeps running), a link to share (a built-in scene's name, or the edited
// scene compressed into the URL's fragment), and downloads (the scene
// file, a PNG of the frame, an animated GIF of the next frames).
//
// window.iskraPage is the page's interface for scripts (tools/web_test.py
// drives the page through it and through real pointer events).
'use strict';

// ---- WASI: what the C library asks of its system --------------------------
// The module has no files: stdout and stderr go to the console, every other
// descriptor is refused, and no path exists ("No such file or directory").
// Errno values of wasi_snapshot_preview1.
const WASI_EBADF = 8, WASI_ENOENT = 44, WASI_ESPIPE = 70;

function wasiImports(getMemory) {
  const pending = ['', '', ''];
  const view = () => new DataView(getMemory().buffer);
  const bytes = () => new Uint8Array(getMemory().buffer);
  return {
    environ_sizes_get(count, size) { view().setUint32(count, 0, true); view().setUint32(size, 0, true); return 0; },
    environ_get() { return 0; },
    // Only the tool's cost measurements read a clock (never the library).
    clock_time_get(id, precision, out) {
      view().setBigUint64(out, BigInt(Math.round(performance.now() * 1e6)), true);
      return 0;
    },
    fd_write(fd, iovs, n, written) {
      if (fd !== 1 && fd !== 2) return WASI_EBADF;
      const v = view();
      let total = 0;
      for (let i = 0; i < n; i++) {
        const ptr = v.getUint32(iovs + 8 * i, true), len = v.getUint32(iovs + 8 * i + 4, true);
        pending[fd] += new TextDecoder().decode(bytes().slice(ptr, ptr + len));
        total += len;
      }
      const lines = pending[fd].split('\n');
      pending[fd] = lines.pop();
      for (const line of lines) (fd === 2 ? console.warn : console.log)('iskra: ' + line);
      v.setUint32(written, total, true);
      return 0;
    },
    fd_read(fd, iovs, n, read) { if (fd !== 0) return WASI_EBADF; view().setUint32(read, 0, true); return 0; },
    fd_close(fd) { return fd <= 3 ? 0 : WASI_EBADF; },
    fd_seek(fd) { return fd <= 2 ? WASI_ESPIPE : WASI_EBADF; },
    fd_sync(fd) { return fd <= 2 ? 0 : WASI_EBADF; },
    fd_fdstat_get(fd, out) {
      if (fd > 3) return WASI_EBADF;
      const v = view();
      v.setUint8(out, fd === 3 ? 3 : 2);            // the directory, or a character device
      v.setUint16(out + 2, 0, true);                // no flags
      v.setBigUint64(out + 8, 0xffffffffn, true);   // rights
      v.setBigUint64(out + 16, 0xffffffffn, true);
      return 0;
    },
    fd_filestat_get(fd, out) {
      if (fd > 3) return WASI_EBADF;
      bytes().fill(0, out, out + 64);
      view().setUint8(out + 16, fd === 3 ? 3 : 2);  // the directory, or a character device
      return 0;
    },
    fd_fdstat_set_flags(fd) { return fd <= 2 ? 0 : WASI_EBADF; },
    // One directory, "/", empty: so a path is looked up, and is not there.
    fd_prestat_get(fd, out) {
      if (fd !== 3) return WASI_EBADF;
      view().setUint8(out, 0);                      // a directory
      view().setUint32(out + 4, 1, true);           // its name's length
      return 0;
    },
    fd_prestat_dir_name(fd, path, len) {
      if (fd !== 3 || len < 1) return WASI_EBADF;
      bytes()[path] = 47;                           // "/"
      return 0;
    },
    path_open() { return WASI_ENOENT; },
    path_filestat_get() { return WASI_ENOENT; },
    path_create_directory() { return WASI_ENOENT; },
    path_rename() { return WASI_ENOENT; },
    path_unlink_file() { return WASI_ENOENT; },
    proc_exit(code) { throw new Error('iskra exited with status ' + code); },
  };
}

// ---- the module, with strings both ways --------------------------------------
class Iskra {
  static async load(url) {
    let memory = null;
    const imports = { wasi_snapshot_preview1: wasiImports(() => memory) };
    const response = await fetch(url);
    const { instance } = await WebAssembly.instantiateStreaming(response, imports);
    memory = instance.exports.memory;
    instance.exports._initialize();
    return new Iskra(instance.exports);
  }
  constructor(exports) { this.x = exports; }
  bytes() { return new Uint8Array(this.x.memory.buffer); }
  string(ptr) {
    if (!ptr) return null;
    const b = this.bytes();
    let end = ptr;
    while (b[end]) end++;
    return new TextDecoder().decode(b.subarray(ptr, end));
  }
  // Calls fn with each string argument copied into the module's memory.
  withStrings(strings, fn) {
    const ptrs = strings.map((s) => {
      if (s === null || s === undefined) return 0;
      const utf8 = new TextEncoder().encode(s);
      const p = this.x.iskra_web_alloc(utf8.length + 1);
      this.bytes().set(utf8, p);
      this.bytes()[p + utf8.length] = 0;
      return p;
    });
    try { return fn(...ptrs); } finally { for (const p of ptrs) if (p) this.x.iskra_web_free(p); }
  }
  message() { return this.string(this.x.iskra_web_message()); }
  builtins() {
    const names = [];
    for (let i = 0; i < this.x.iskra_web_builtin_count(); i++) names.push(this.string(this.x.iskra_web_builtin_name(i)));
    return names;
  }
  builtinText(name) { return this.withStrings([name], (p) => this.string(this.x.iskra_web_builtin_text(p))); }
  // RGBA rows without padding, as ImageData wants them.
  pixels(ptr, w, h, stride) {
    const out = new Uint8ClampedArray(w * h * 4), b = this.bytes();
    for (let y = 0; y < h; y++) out.set(b.subarray(ptr + y * stride, ptr + y * stride + w * 4), y * w * 4);
    return out;
  }
}

// ---- helpers ------------------------------------------------------------------
async function sha256(bytes) {
  const d = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
  return Array.from(d, (b) => b.toString(16).padStart(2, '0')).join('');
}
async function squeeze(text) {       // text -> deflate -> base64url
  const s = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate'));
  const b = new Uint8Array(await new Response(s).arrayBuffer());
  let bin = '';
  for (const x of b) bin += String.fromCharCode(x);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}
async function unsqueeze(code) {
  const bin = atob(code.replace(/-/g, '+').replace(/_/g, '/'));
  const b = Uint8Array.from(bin, (c) => c.charCodeAt(0));
  const s = new Blob([b]).stream().pipeThrough(new DecompressionStream('deflate'));
  return new Response(s).text();
}
function download(name, bytes, type) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([bytes], { type }));
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

// Keys as iskra/sdl.h codes: printable keys are their lower-case ASCII.
const KEY_CODES = {
  Backspace: 8, Tab: 9, Enter: 13, Escape: 27, ' ': 32, Delete: 127,
  ArrowLeft: 0x10d, ArrowRight: 0x10e, ArrowUp: 0x10f, ArrowDown: 0x110, Home: 0x113, End: 0x114,
};
for (let i = 1; i <= 12; i++) KEY_CODES['F' + i] = 0x100 + i;
const EV = { KEY_DOWN: 2, KEY_UP: 3, MOUSE_DOWN: 4, MOUSE_UP: 5, MOUSE_MOVE: 6, WHEEL: 7 };
function keyCode(e) {
  if (e.code === 'NumpadAdd') return 0x111;
  if (e.code === 'NumpadSubtract') return 0x112;
  if (KEY_CODES[e.key] !== undefined) return KEY_CODES[e.key];
  if (e.key.length === 1) { const c = e.key.toLowerCase().charCodeAt(0); return c < 128 ? c : 0; }
  return 0;
}
function mods(e) { return (e.shiftKey ? 1 : 0) | (e.ctrlKey || e.metaKey ? 2 : 0) | (e.altKey ? 4 : 0); }

// ---- the page --------------------------------------------------------------------
class Page {
  constructor(iskra, el) {
    this.iskra = iskra;
    this.el = el;
    this.ctx = el.screen.getContext('2d');
    this.scene = null;        // the built-in scene's name, or null for an edited scene
    this.edited = null;       // the edited scene's text that runs, or null
    this.fixedClock = new URLSearchParams(location.search).has('fixed-clock');
    this.running = false;
    this.last = 0;
    this.lastDown = { t: -1e9, x: 0, y: 0 };
    this.scale = 1;
  }

  say(text, isError) {
    this.el.status.textContent = text || '';
    this.el.status.className = isError ? 'error' : '';
  }

  // The screen the simulator lays itself out for: the whole window (the
  // page's own controls are below it).
  screenSize() {
    return [Math.max(320, Math.floor(window.innerWidth)), Math.max(200, Math.floor(window.innerHeight))];
  }

  open(name) {
    const [w, h] = this.screenSize();
    const rc = this.iskra.withStrings([name, null], (n, t) => this.iskra.x.iskra_web_open(n, t, w, h, this.fixedClock ? 1 : 0));
    if (rc !== 0) { this.say(this.iskra.message(), true); return false; }
    this.scene = name;
    this.edited = null;
    this.el.picker.value = name;
    this.el.editor.value = this.iskra.builtinText(name) || '';
    this.el.editorMessage.textContent = '';
    this.say('');
    this.show();
    return true;
  }

  // The editor's text onto the running scene; a mistake keeps the old one.
  apply(text) {
    const rc = this.iskra.withStrings(['scene.ini', text], (n, t) => this.iskra.x.iskra_web_apply(n, t));
    if (rc !== 0) {
      const m = this.iskra.message();
      this.el.editorMessage.textContent = m;
      this.say(m, true);
      return m;
    }
    this.scene = null;
    this.edited = text;
    this.el.editorMessage.textContent = '';
    this.say('applied');
    this.show();
    return '';
  }

  // The window's canvas into the HTML canvas, scaled by a whole number.
  show() {
    const x = this.iskra.x, w = x.iskra_web_width(), h = x.iskra_web_height();
    if (!w || !h) return;
    const c = this.el.screen;
    if (c.width !== w || c.height !== h || this.zoom !== this.iskra.x.iskra_web_zoom()) {
      c.width = w;
      c.height = h;
      this.zoom = this.iskra.x.iskra_web_zoom();
      this.fit();
    }
    const px = this.iskra.pixels(x.iskra_web_pixels(), w, h, x.iskra_web_stride());
    this.ctx.putImageData(new ImageData(px, w, h), 0, 0);
    this.takeFile();
  }

  // The zoom the simulator chose for the window when the scene opened
  // (iskra_web_zoom), less if the window has shrunk since: a whole number.
  fit() {
    const c = this.el.screen, [sw, sh] = this.screenSize();
    const fitting = Math.floor(Math.min(sw / c.width, sh / c.height));
    this.scale = Math.max(1, Math.min(this.iskra.x.iskra_web_zoom(), fitting));
    c.style.width = c.width * this.scale + 'px';
    c.style.height = c.height * this.scale + 'px';
  }

  frame(dt) {
    const stopped = this.iskra.x.iskra_web_frame(dt);
    this.show();
    const m = this.iskra.message();
    if (m) this.say(m, true);
    return stopped;
  }

  loop(t) {
    const dt = this.last ? (t - this.last) / 1000 : 0;
    this.last = t;
    if (this.frame(dt)) { this.running = false; this.say(this.iskra.message() || 'stopped (choose a scene to start again)'); return; }
    requestAnimationFrame((u) => this.loop(u));
  }

  start() {
    if (this.running || this.fixedClock) return;
    this.running = true;
    this.last = 0;
    requestAnimationFrame((t) => this.loop(t));
  }

  takeFile() {
    const x = this.iskra.x, name = this.iskra.string(x.iskra_web_file_name());
    if (!name) return;
    const ptr = x.iskra_web_file_bytes(), n = x.iskra_web_file_size();
    const bytes = this.iskra.bytes().slice(ptr, ptr + n);
    x.iskra_web_file_taken();
    this.lastFile = { name, bytes };
    const type = name.endsWith('.png') ? 'image/png' : name.endsWith('.gif') ? 'image/gif' : 'text/plain';
    if (!this.fixedClock) download(name, bytes, type);
    this.say('downloaded ' + name);
  }

  // Pointer position in window-canvas pixels.
  at(e) {
    const r = this.el.screen.getBoundingClientRect();
    return [Math.floor((e.clientX - r.left) * this.el.screen.width / r.width),
            Math.floor((e.clientY - r.top) * this.el.screen.height / r.height)];
  }

  event(type, e, extra) {
    const [px, py] = e ? this.at(e) : [0, 0];
    const o = Object.assign({ key: 0, button: 0, wheel: 0, mods: 0, clicks: 0 }, extra);
    this.iskra.x.iskra_web_event(type, o.key, o.button, px, py, o.wheel, o.mods, o.clicks);
  }

  listen() {
    const c = this.el.screen;
    c.addEventListener('pointerdown', (e) => {
      c.focus();
      c.setPointerCapture(e.pointerId);
      const [x, y] = this.at(e), now = e.timeStamp;
      const double = now - this.lastDown.t < 400 && Math.abs(x - this.lastDown.x) < 4 && Math.abs(y - this.lastDown.y) < 4;
      this.lastDown = double ? { t: -1e9, x, y } : { t: now, x, y };
      this.event(EV.MOUSE_MOVE, e);
      this.event(EV.MOUSE_DOWN, e, { button: e.button + 1, clicks: double ? 2 : 1 });
      e.preventDefault();
    });
    c.addEventListener('pointerup', (e) => { this.event(EV.MOUSE_UP, e, { button: e.button + 1, clicks: 1 }); e.preventDefault(); });
    c.addEventListener('pointermove', (e) => this.event(EV.MOUSE_MOVE, e));
    c.addEventListener('wheel', (e) => { this.event(EV.WHEEL, e, { wheel: e.deltaY < 0 ? 1 : -1 }); e.preventDefault(); }, { passive: false });
    c.addEventListener('contextmenu', (e) => e.preventDefault());
    c.addEventListener('keydown', (e) => {
      const key = keyCode(e);
      this.event(EV.KEY_DOWN, null, { key, mods: mods(e) });
      if (e.key.length === 1 && !e.ctrlKey && !e.metaKey && !e.altKey) this.iskra.withStrings([e.key], (p) => this.iskra.x.iskra_web_text(p));
      if (key) e.preventDefault();
    });
    c.addEventListener('keyup', (e) => this.event(EV.KEY_UP, null, { key: keyCode(e), mods: mods(e) }));
    window.addEventListener('resize', () => this.fit());

    const el = this.el;
    el.picker.addEventListener('change', () => { if (this.open(el.picker.value)) history.replaceState(null, '', '#scene=' + el.picker.value); });
    el.apply.addEventListener('click', () => this.apply(el.editor.value));
    el.editor.addEventListener('keydown', (e) => { if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) { this.apply(el.editor.value); e.preventDefault(); } });
    el.share.addEventListener('click', async () => {
      const link = await this.link();
      history.replaceState(null, '', link);
      try { await navigator.clipboard.writeText(location.href); this.say('link copied'); } catch { this.say('link in the address bar'); }
    });
    el.saveScene.addEventListener('click', () => {
      const p = this.iskra.x.iskra_web_scene_text();
      if (!p) { this.say(this.iskra.message(), true); return; }
      const text = this.iskra.string(p);
      this.iskra.x.iskra_web_free(p);
      download((this.scene || 'scene') + '.ini', new TextEncoder().encode(text), 'text/plain');
    });
    el.png.addEventListener('click', () => this.press('shot'));
    el.gif.addEventListener('click', () => {
      const n = Number(el.gifFrames.value);
      if (this.iskra.x.iskra_web_gif(n) !== 0) this.say(this.iskra.message(), true);
      else this.say('recording ' + n + ' frames');
    });
  }

  // A screenshot of the scene's canvas: F12, as the simulator's key.
  press(what) {
    if (what === 'shot') this.event(EV.KEY_DOWN, null, { key: 0x10c });
  }

  async link() {
    const base = location.href.split('#')[0];
    if (this.edited === null) return base + '#scene=' + encodeURIComponent(this.scene);
    return base + '#text=' + await squeeze(this.edited);
  }

  // What the URL's fragment asks for: #scene=NAME or #text=DEFLATED.
  async fromFragment() {
    const f = new URLSearchParams(location.hash.slice(1));
    if (f.has('text')) {
      let text;
      try { text = await unsqueeze(f.get('text')); } catch { this.say('the link\'s scene is damaged', true); return false; }
      this.el.editor.value = text;
      return this.apply(text) === '';
    }
    if (f.has('scene')) return this.open(f.get('scene'));
    return false;
  }
}

// ---- start ---------------------------------------------------------------------------
async function main() {
  const $ = (id) => document.getElementById(id);
  const el = {
    screen: $('screen'), bar: $('bar'), status: $('status'), picker: $('picker'), editor: $('editor'),
    editorMessage: $('editor-message'), apply: $('apply'), share: $('share'), saveScene: $('save-scene'),
    png: $('png'), gif: $('gif'), gifFrames: $('gif-frames'),
  };
  el.status.textContent = 'loading iskra.wasm ...';
  const iskra = await Iskra.load(new URL('iskra.wasm', location.href));
  for (const name of iskra.builtins()) {
    const o = document.createElement('option');
    o.value = o.textContent = name;
    el.picker.appendChild(o);
  }
  const page = new Page(iskra, el);
  page.listen();
  window.iskraPage = testInterface(page);
  if (!(await page.fromFragment())) page.open(iskra.builtins().includes('fig22_simulator_regular') ? 'fig22_simulator_regular' : iskra.builtins()[0]);
  page.start();
  document.body.dataset.ready = '1';
}

// What scripts (the tests) may ask of the page.
function testInterface(page) {
  const x = page.iskra.x;
  return {
    open: (name) => page.open(name) ? '' : page.iskra.message(),
    apply: (text) => page.apply(text),
    frames(n) { for (let i = 0; i < n; i++) page.frame(1 / 60); return x.iskra_web_scene_frame(); },
    sceneHash: () => sha256(page.iskra.pixels(x.iskra_web_scene_pixels(), x.iskra_web_scene_width(), x.iskra_web_scene_height(), x.iskra_web_scene_stride())),
    windowHash: () => sha256(page.iskra.pixels(x.iskra_web_pixels(), x.iskra_web_width(), x.iskra_web_height(), x.iskra_web_stride())),
    renderHash(name, frames) {
      const rc = page.iskra.withStrings([name], (p) => x.iskra_web_render(p, frames));
      if (rc !== 0) return Promise.resolve('error: ' + page.iskra.message());
      return sha256(page.iskra.pixels(x.iskra_web_render_pixels(), x.iskra_web_render_width(), x.iskra_web_render_height(), x.iskra_web_render_stride()));
    },
    builtins: () => page.iskra.builtins(),
    builtinText: (name) => page.iskra.builtinText(name),
    sceneText() { const p = x.iskra_web_scene_text(); const t = page.iskra.string(p); x.iskra_web_free(p); return t; },
    size: () => [x.iskra_web_width(), x.iskra_web_height(), page.scale],
    message: () => page.iskra.message(),
    editorMessage: () => page.el.editorMessage.textContent,
    link: () => page.link(),
    lastFile: () => page.lastFile ? [page.lastFile.name, page.lastFile.bytes.length] : null,
    particles: () => x.iskra_web_particle_count(),
    // A widget's rectangle in viewport pixels (CSS), for real pointer events.
    widget(name) {
      const out = x.iskra_web_alloc(16);
      const found = page.iskra.withStrings([name], (p) => x.iskra_web_widget_rect(p, out));
      const r = new Int32Array(x.memory.buffer, out, 4).slice();
      x.iskra_web_free(out);
      if (!found) return null;
      const c = page.el.screen.getBoundingClientRect(), k = c.width / page.el.screen.width;
      return [c.left + r[0] * k, c.top + r[1] * k, r[2] * k, r[3] * k];
    },
    press: (what) => page.press(what),
  };
}

main().catch((e) => {
  const s = document.getElementById('status');
  s.textContent = 'iskra could not start: ' + e.message;
  s.className = 'error';
  document.body.dataset.ready = 'failed';
});
