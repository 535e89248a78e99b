// SPDX-License-Identifier: MIT
// Times the kernels of bench.wasm (web/bench_web.c, bench/web/web_kernels.h)
// with performance.now(): each kernel's warm-up runs, then its timed runs,
// their median, and the hash of its bytes afterwards.  The same for
// bench-nosimd.wasm, the same C built without -msimd128.
//
// window.iskraBench.run(url) is what tools/web_bench.py calls; the page's
// Run button shows the same figures in a table.
'use strict';

// ---- WASI --------------------------------------------------------------------
// The kernels write nothing and read no file or clock, so the module needs
// next to nothing of its system.  (web/iskra.js has the simulator's fuller
// shim, but it is a classic script that starts the simulator when loaded,
// not a module to import from.)  What the module imports and is not here
// throws, naming itself.
const WASI_EBADF = 8;

function wasiImports(module, getMemory) {
  const known = {
    fd_write(fd, iovs, n, written) {         // stdout and stderr to the console
      if (fd !== 1 && fd !== 2) return WASI_EBADF;
      const v = new DataView(getMemory().buffer);
      let total = 0, text = '';
      for (let i = 0; i < n; i++) {
        const ptr = v.getUint32(iovs + 8 * i, true), len = v.getUint32(iovs + 8 * i + 4, true);
        text += new TextDecoder().decode(new Uint8Array(getMemory().buffer, ptr, len));
        total += len;
      }
      (fd === 2 ? console.warn : console.log)('bench: ' + text);
      v.setUint32(written, total, true);
      return 0;
    },
    environ_sizes_get(count, size) {
      const v = new DataView(getMemory().buffer);
      v.setUint32(count, 0, true);
      v.setUint32(size, 0, true);
      return 0;
    },
    environ_get() { return 0; },
    proc_exit(code) { throw new Error('bench.wasm exited with status ' + code); },
  };
  const wasi = {};
  for (const imp of WebAssembly.Module.imports(module)) {
    if (imp.module !== 'wasi_snapshot_preview1') continue;
    wasi[imp.name] = known[imp.name] || (() => { throw new Error('bench.wasm: WASI ' + imp.name + ' is not provided'); });
  }
  return { wasi_snapshot_preview1: wasi };
}

async function loadBench(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(url + ': ' + response.status + ' ' + response.statusText);
  const module = await WebAssembly.compile(await response.arrayBuffer());
  let memory = null;
  const instance = await WebAssembly.instantiate(module, wasiImports(module, () => memory));
  memory = instance.exports.memory;
  instance.exports._initialize();
  return instance.exports;
}

function cString(x, ptr) {
  if (!ptr) return null;
  const b = new Uint8Array(x.memory.buffer);
  let end = ptr;
  while (b[end]) end++;
  return new TextDecoder().decode(b.subarray(ptr, end));
}

function median(v) {
  const s = v.slice().sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

// One kernel: its warm-up runs, its timed runs, the hash of its bytes.
function runKernel(x, id) {
  const k = x.bench_web_setup(id);
  if (!k) throw new Error(cString(x, x.bench_web_name(id)) + ': ' + cString(x, x.bench_web_message()));
  const warm = x.bench_web_warm(id), timed = x.bench_web_timed(id), ms = [];
  try {
    for (let r = 0; r < warm + timed; r++) {
      const t0 = performance.now();
      const status = x.bench_web_run(k);
      const t1 = performance.now();
      if (status !== 0) throw new Error(cString(x, x.bench_web_name(id)) + ': run failed, status ' + status);
      if (r >= warm) ms.push(t1 - t0);
    }
    return {
      name: cString(x, x.bench_web_name(id)), what: cString(x, x.bench_web_what(id)), ms: median(ms), runs: timed,
      hash: BigInt.asUintN(64, x.bench_web_hash(k)).toString(16).padStart(16, '0'),
    };
  } finally {
    x.bench_web_free(k);
  }
}

// Every kernel of the module at url, in order.
async function runBench(url) {
  const x = await loadBench(url);
  const out = [];
  for (let id = 0; id < x.bench_web_count(); id++) out.push(runKernel(x, id));
  return out;
}

// ---- the page ----------------------------------------------------------------
const MODULES = [['bench.wasm', 'simd128'], ['bench-nosimd.wasm', 'no simd']];

async function showAll() {
  const status = document.getElementById('status'), table = document.getElementById('results');
  document.getElementById('run').disabled = true;
  status.className = '';
  table.textContent = '';
  const head = table.insertRow();
  for (const h of ['module', 'kernel', 'median ms', 'hash', 'what']) head.appendChild(document.createElement('th')).textContent = h;
  try {
    for (const [url, label] of MODULES) {
      status.textContent = 'running ' + url + ' ...';
      await new Promise((r) => setTimeout(r, 50));   // let the status show before the tab is busy
      for (const k of await runBench(url)) {
        const row = table.insertRow();
        const cells = [label, k.name, k.ms.toFixed(3), k.hash, k.what];
        cells.forEach((c, i) => { const td = row.insertCell(); td.textContent = c; td.className = ['', '', 'ms', 'hash', ''][i]; });
      }
    }
    status.textContent = 'done';
  } catch (e) {
    status.textContent = e.message;
    status.className = 'error';
  }
  document.getElementById('run').disabled = false;
}

window.iskraBench = { run: runBench };
document.getElementById('run').addEventListener('click', showAll);
document.body.dataset.ready = '1';
