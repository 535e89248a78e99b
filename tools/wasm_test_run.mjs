// SPDX-License-Identifier: MIT
// Runs the library's unit tests built for wasm32-wasi (make test-web-unit)
// under Node's WASI, from the repository root, which is the module's only
// directory (preopened as ".": the tests read and write relative paths).
//
//   node --no-warnings tools/wasm_test_run.mjs [--skip tests/wasm/skip.txt] MODULE.wasm...
//
// Each module is a tests/test_*.c with tests/wasm/runner.c: asked for its
// tests (--list), then run once per test (--run ID) in a fresh instance of
// the module compiled once, as Criterion runs each test in a fresh process
// (a failed cr_assert ends the instance).  Prints one line per module,
// the failed tests' output under it, and a closing line
// "wasm: N passed, M failed, K skipped"; exits with 1 when a test failed.
//
// The skip file has one entry a line, "NAME  reason" ('#' starts a
// comment): NAME is a test file (test_png), left out of the build by the
// Makefile, or tests of a module, FILE::SUITE::TEST, run as skipped; '*'
// in those stands for any part of a name (test_*::refimg::*).  Every entry
// must match a test file or a test, and give a reason.
//
// Node's WASI calls its functions through V8's fast API calls, which can
// crash the process when the garbage collector runs during one (a Node bug,
// seen with many instances in one process): this script runs itself again
// with them turned off.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';

const NODE_FLAGS = ['--no-warnings', '--no-turbo-fast-api-calls'];
if (!NODE_FLAGS.every((f) => process.execArgv.includes(f))) {
    const again = spawnSync(process.execPath, [...NODE_FLAGS, ...process.argv.slice(1)], { stdio: 'inherit' });
    process.exit(again.status ?? 1);
}
const { WASI } = await import('node:wasi');

const EXIT_PASSED = 0;
const EXIT_SKIPPED = 77;

function usage(message) {
    console.error(`wasm_test_run: ${message}`);
    console.error('usage: node tools/wasm_test_run.mjs [--skip FILE] MODULE.wasm...');
    process.exit(2);
}

// The skip file's entries: [{ name, reason, match (per-test entries), used }].
function readSkips(file) {
    const skips = [];
    fs.readFileSync(file, 'utf8').split('\n').forEach((raw, i) => {
        const line = raw.replace(/#.*/, '').trim();
        if (!line) return;
        const m = line.match(/^(test_\w+|test_[\w*]+::[\w*]+::[\w*]+(?:\/\d+)?)\s+(\S.*)$/);
        if (!m) usage(`${file}:${i + 1}: not "test_FILE[::SUITE::TEST]  reason": ${raw}`);
        if (skips.some((s) => s.name === m[1])) usage(`${file}:${i + 1}: ${m[1]} is listed twice`);
        const glob = m[1].split('*').map((part) => part.replace(/[.+?^${}()|[\]\\/]/g, '\\$&')).join('[^:]*');
        skips.push({ name: m[1], reason: m[2], match: m[1].includes('::') ? new RegExp(`^${glob}$`) : null, used: false });
    });
    return skips;
}

// Runs one instance of the module with these arguments; its stdout and
// stderr go to one file, returned with the exit status (or the trap).
function runInstance(module, name, args, outFile) {
    const fd = fs.openSync(outFile, 'w+');
    const wasi = new WASI({
        version: 'preview1',
        args: [name, ...args],
        env: process.env,
        preopens: { '.': process.cwd() },
        stdout: fd,
        stderr: fd,
        returnOnExit: true,
    });
    let status;
    let trap = null;
    try {
        const instance = new WebAssembly.Instance(module, wasi.getImportObject());
        status = wasi.start(instance);
    } catch (e) {
        trap = e instanceof WebAssembly.RuntimeError ? `trap: ${e.message}` : String(e);
        status = -1;
    }
    fs.closeSync(fd);
    const output = fs.readFileSync(outFile, 'utf8');
    return { status, trap, output };
}

function seconds(ms) {
    return `${(ms / 1000).toFixed(1)} s`;
}

const argv = process.argv.slice(2);
let skips = [];
let skipFile = null;
if (argv[0] === '--skip') {
    if (argv.length < 2) usage('--skip needs a file');
    skipFile = argv[1];
    skips = readSkips(skipFile);
    argv.splice(0, 2);
}
if (argv.length === 0) usage('no modules given');

// A file entry names a test file that exists, whose module is not built.
const modules = new Set(argv.map((m) => path.basename(m, '.wasm')));
for (const skip of skips.filter((s) => !s.match)) {
    if (!fs.existsSync(`tests/${skip.name}.c`)) usage(`${skipFile}: ${skip.name}: there is no tests/${skip.name}.c`);
    if (modules.has(skip.name)) usage(`${skipFile}: ${skip.name} is left out, yet its module was given`);
}

const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'iskra-wasm-test-'));
const totals = { passed: 0, failed: 0, skipped: 0 };
const failedFiles = [];
const t0 = Date.now();
for (const file of argv) {
    const name = path.basename(file, '.wasm');
    const started = Date.now();
    const module = new WebAssembly.Module(fs.readFileSync(file));
    const outFile = path.join(scratch, `${name}.out`);
    const listed = runInstance(module, name, ['--list'], outFile);
    if (listed.status !== EXIT_PASSED) {
        console.log(`FAIL ${name}: --list ended with ${listed.trap ?? `status ${listed.status}`}`);
        console.log(listed.output.trimEnd());
        totals.failed++;
        failedFiles.push(name);
        continue;
    }
    const ids = listed.output.split('\n').filter((l) => l);
    const counts = { passed: 0, failed: 0, skipped: 0 };
    const reports = [];
    for (const id of ids) {
        const skip = skips.find((s) => s.match && s.match.test(`${name}::${id}`));
        if (skip) {
            skip.used = true;
            counts.skipped++;
            reports.push(`  skip ${id}: ${skip.reason}`);
            continue;
        }
        const run = runInstance(module, name, ['--run', id], outFile);
        if (run.status === EXIT_PASSED) {
            counts.passed++;
        } else if (run.status === EXIT_SKIPPED) {
            counts.skipped++;
            const why = run.output.split('\n').find((l) => l.startsWith('skip ')) ?? `skip ${id}`;
            reports.push(`  ${why}`);
        } else {
            counts.failed++;
            const tail = run.output.trimEnd().split('\n').slice(-20).join('\n    ');
            reports.push(`  FAIL ${id}: ${run.trap ?? `exit status ${run.status}`}\n    ${tail}`);
        }
    }
    for (const k of Object.keys(totals)) totals[k] += counts[k];
    if (counts.failed) failedFiles.push(name);
    const skipped = counts.skipped ? `, ${counts.skipped} skipped` : '';
    const failed = counts.failed ? `, ${counts.failed} failed` : '';
    console.log(`${counts.failed ? 'FAIL' : 'ok  '} ${name.padEnd(32)} ${counts.passed} passed${failed}${skipped} (${seconds(Date.now() - started)})`);
    for (const r of reports) console.log(r);
}
fs.rmSync(scratch, { recursive: true, force: true });

// A test entry of one file that matched no test of its module is stale
// (the test was renamed or removed).
for (const skip of skips.filter((s) => s.match && !s.used && modules.has(s.name.split('::')[0]))) {
    console.log(`FAIL ${skipFile}: ${skip.name} matches no test`);
    totals.failed++;
}
const leftOut = skips.filter((s) => !s.match).length;
console.log(`wasm: ${totals.passed} passed, ${totals.failed} failed, ${totals.skipped} skipped in ${argv.length} test files ` +
    `(${leftOut} left out: ${skipFile ?? 'no skip file'}) in ${seconds(Date.now() - t0)}`);
if (failedFiles.length) console.log(`wasm: failed: ${failedFiles.join(' ')}`);
process.exit(totals.failed ? 1 : 0);
