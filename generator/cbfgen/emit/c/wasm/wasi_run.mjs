// Runs a WASI command (build/wasm/cbf-c.wasm, build/wasm/cbf_testee.wasm) under node's own
// node:wasi, with no npm package: `node --disable-warning=ExperimentalWarning wasi_run.mjs
// MODULE.wasm ARGS...`. The module sees the whole file system at its real paths (one preopen of
// "/"), so the paths a user or the conformance runner gives mean what they mean to native cbf-c.
// Its exit status is the module's. (issue 34, point 2: the c-wasm binding.)
import { constants, fstatSync, openSync, readFileSync } from 'node:fs';
import { argv, exit, stderr } from 'node:process';
import { WASI } from 'node:wasi';

const [modulePath, ...args] = argv.slice(2);
if (modulePath === undefined) {
  stderr.write('usage: node wasi_run.mjs MODULE.wasm [ARGS...]\n');
  exit(2);
}

// node may have made its fds 0, 1 and 2 non-blocking; WASI's fd_read and fd_write on them then fail
// with EAGAIN whenever a pipe is momentarily empty or full, and the module sees the end of its input
// (the testee would stop after its first request) or a failed write (a long answer cut short). A
// second open of the same pipe or terminal is a file description of its own, blocking. A regular
// file keeps its fd (a new open would not share its offset).
function blocking(fd, name, flags) {
  try {
    const st = fstatSync(fd);
    return st.isFIFO() || st.isCharacterDevice() ? openSync(`/dev/${name}`, flags) : fd;
  } catch {
    return fd;
  }
}

const wasi = new WASI({
  version: 'preview1',
  args: [modulePath, ...args],
  env: {},
  preopens: { '/': '/' },
  stdin: blocking(0, 'stdin', constants.O_RDONLY),
  stdout: blocking(1, 'stdout', constants.O_WRONLY),
  stderr: blocking(2, 'stderr', constants.O_WRONLY),
  returnOnExit: true,
});
const module = await WebAssembly.compile(readFileSync(modulePath));
const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
exit(wasi.start(instance));
