// `make bench`'s wasm row (issue 34, point 6): node wasm_time.mjs MODULE.wasm REPS ARGS... runs the
// WASI command MODULE (cbf-c.wasm) with ARGS as REPS fresh instances of the module, compiled once
// before the first, as the workbench page runs it (one compile per page, one instance per file),
// stdout and stderr to /dev/null. WARMUP untimed runs come first: the page cache, and V8's
// optimising tier of the module's hot functions (its baseline tier compiles first; a page checking
// a second file runs the optimised code). Prints one JSON line: the compile's wall seconds, each
// timed run's wall seconds (instantiate + run) and exit status. Run it with --expose-gc.
import { closeSync, openSync, readFileSync } from 'node:fs';
import { argv, stdout } from 'node:process';
import { performance } from 'node:perf_hooks';
import { WASI } from 'node:wasi';

const WARMUP = 3;
// node:wasi's import functions, each called through a plain JS function, as the page's own WASI layer's
// are (workbench.js, runCommand). Given as they are, V8 spent about 1.2 ms on each instantiation (node
// 20; 0.06 ms through plain functions, the same module, the same run): the harness's cost, neither the
// engine's nor the page's (bench/NOTES.md, round 5).
const plain = (importObject) => Object.fromEntries(Object.entries(importObject).map(([ns, fns]) => [
  ns, Object.fromEntries(Object.entries(fns).map(([name, fn]) => [name, (...a) => fn(...a)]))]));
const [modulePath, repsText, ...args] = argv.slice(2);
const seconds = (since) => (performance.now() - since) / 1e3;
let t = performance.now();
const module = await WebAssembly.compile(readFileSync(modulePath));
const out = { compile_wall_s: seconds(t), wall_s: [], status: [] };
const sink = openSync('/dev/null', 'w');
for (let i = 0; i < WARMUP + Number(repsText); i += 1) {
  // The previous instances' memories are collected before the clock starts (node --expose-gc): each
  // reserves gigabytes of address space, and V8 collects when many are reserved; that is not this
  // run's work (a page holds one instance per file).
  globalThis.gc?.();
  t = performance.now();
  const wasi = new WASI({
    version: 'preview1', args: [modulePath, ...args], env: {}, preopens: { '/': '/' },
    stdout: sink, stderr: sink, returnOnExit: true,
  });
  const instance = await WebAssembly.instantiate(module, plain(wasi.getImportObject()));
  const status = wasi.start(instance);
  if (i >= WARMUP) {
    out.wall_s.push(seconds(t));
    out.status.push(status);
  }
}
closeSync(sink);
stdout.write(`${JSON.stringify(out)}\n`);
