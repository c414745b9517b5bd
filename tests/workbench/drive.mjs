// Drives the workbench page in headless Chromium (playwright-core, Debian's /usr/bin/chromium) for
// tests/test_workbench_page.py: node drive.mjs PAGE.html SHOTS_DIR JOBS.json
// JOBS: {"files": [[PATH, PROFILE], ...], "cuts": [PATH of CUT text dropped, ...], "shot": PATH of a failing file to photograph (optional: `make bench` times the page without, bench/workbench_rows.py), "paged": PATH of
// a file of more than a page of motion records, "curve": [PATH, RECORD] of a curved motion}. Prints JSON:
// each file's printed text and exit status as the page shows them, the requests the page made, the
// console errors, what fetch() gave from inside the page, and the screenshots' paths and page widths.
import { readFileSync } from 'node:fs';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const [pagePath, shots, jobsPath] = process.argv.slice(2);
const jobs = JSON.parse(readFileSync(jobsPath, 'utf-8'));
const url = pathToFileURL(pagePath).href;
// The flags of /work/.library/env/machines/polyglot.md: no background connections on a closed network.
const context = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), 'wb-chromium-')), {
  executablePath: process.env.CBF_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync'],
});
const page = await context.newPage();
const requests = [];
const errors = [];
page.on('request', (r) => requests.push(r.url()));
page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
page.on('pageerror', (e) => { errors.push(String(e)); process.stderr.write(`page error: ${e}\n`); });
await page.goto(url);
// As a reader does: pick the profile, choose the file; then wait until the page has shown that file
// under that profile, and no newer request is pending.
async function feed(path, profile) {
  await page.selectOption('#profile', profile);
  await page.setInputFiles('#file', path);
  const name = path.split('/').pop();
  // polled from here: Playwright's waitForFunction evaluates a string in the page, which the page's
  // Content-Security-Policy refuses (no 'unsafe-eval'), as it should
  for (let waited = 0; ; waited += 20) {
    const done = await page.evaluate(([n, p]) => {
      const d = document.body.dataset;
      return d.file === n && d.profile === p && d.done === d.generation;
    }, [name, profile]);
    if (done) return;
    if (waited > 60000) throw new Error(`the page did not show ${name} under ${profile} within 60 s`);
    await new Promise((r) => { setTimeout(r, 20); });
  }
}
const results = [];
// The toolpath's Tab stops, a page of records at a time: the top view's focusable segments and the
// records of the records' page, on this page and on the next.
const tabStops = () => page.evaluate(() => ({
  tabbable: [...new Set([...document.querySelectorAll('#path-top path[tabindex="0"]')].map((p) => p.dataset.record))],
  rows: [...document.querySelectorAll('#records tbody tr')].map((r) => r.dataset.record),
  segments: document.querySelectorAll('#path-top path').length,
}));
let paged = null;
let curve = null;
for (const [path, profile] of jobs.files) {
  const t0 = performance.now();
  await feed(path, profile);
  const ms = performance.now() - t0; // choosing the file to its findings shown (polled every 20 ms)
  results.push({ path, profile, ms, text: await page.textContent('#raw'),
    status: Number(await page.getAttribute('#verdict', 'data-status')) });
  if (path === jobs.paged && paged === null) {
    const first = await tabStops();
    await page.click('#next');
    paged = [first, await tabStops()];
  }
  if (jobs.curve && path === jobs.curve[0] && curve === null) { // the points the top view draws for the curve's record
    curve = await page.evaluate((r) => [...document.querySelectorAll(`#path-top path[data-record="${r}"]`)]
      .map((p) => p.getAttribute('d')), String(jobs.curve[1]));
  }
}
// CUT text dropped onto the page (issue 34): each file as a drop event carries it; what the page prints for
// the CBF it encodes to, its note, and (for the first) the CBF the download link gives.
const cuts = [];
async function dropFile(path) {
  const name = path.split('/').pop();
  const bytes = [...readFileSync(path)];
  await page.selectOption('#profile', 'default');
  await page.evaluate(([n, b]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([new Uint8Array(b)], n));
    document.getElementById('drop').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, bytes]);
  for (let waited = 0; ; waited += 20) {
    const done = await page.evaluate((n) => {
      const d = document.body.dataset;
      return d.file === n && d.done === d.generation;
    }, name);
    if (done) return;
    if (waited > 60000) throw new Error(`the page did not show the dropped ${name} within 60 s`);
    await new Promise((r) => { setTimeout(r, 20); });
  }
}
for (const [k, path] of (jobs.cuts || []).entries()) {
  await dropFile(path);
  const shown = await page.evaluate(() => ({
    shown: document.body.dataset.shown, note: document.getElementById('cut-note').hidden ? null
      : document.getElementById('cut-note').textContent,
    href: document.getElementById('cut-download').getAttribute('href'),
    download: document.getElementById('cut-download').getAttribute('download'),
    verdict: document.getElementById('verdict').textContent,
    records: document.querySelectorAll('#records tbody tr').length,
    segments: document.querySelectorAll('#path-top path[data-record]').length,
  }));
  const r = { path, ...shown, text: await page.textContent('#raw'),
    status: Number(await page.getAttribute('#verdict', 'data-status')) };
  if (k === 0 && shown.note !== null) {
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#cut-download')]);
    r.downloaded = [...readFileSync(await dl.path())];
    await page.setViewportSize({ width: 1280, height: 900 });
    await page.screenshot({ path: join(shots, 'workbench-cut-1280.png'), fullPage: true });
  }
  cuts.push(r);
}
// Nothing leaves the page: a fetch() from inside it is refused by the Content-Security-Policy.
const fetched = await page.evaluate(async () => {
  const out = [];
  for (const u of ['https://example.com/', 'http://127.0.0.1:9/', 'data:text/plain,x']) {
    try { await fetch(u); out.push(`${u} fetched`); } catch (e) { out.push(`${u} refused`); }
  }
  return out;
});
let selected = null;
const picked = [];
let three = null;
const widths = {};
if (jobs.shot) {
  // Screenshots of a failing file with its first finding selected, at 390 and 1280 px.
  await feed(jobs.shot, 'default');
  await page.focus('#findings button');
  await page.keyboard.press('Enter');
  selected = await page.evaluate(() => ({
    finding: document.querySelectorAll('#findings .wb-selected').length,
    row: document.querySelectorAll('#records tr.wb-selected').length,
    hit: document.querySelectorAll('#hex .wb-hit').length,
    segments: document.querySelectorAll('.wb-path path.wb-selected').length,
  }));
  for (const w of [390, 1280]) {
    await page.setViewportSize({ width: w, height: 900 });
    widths[w] = await page.evaluate(() => document.documentElement.scrollWidth);
    await page.screenshot({ path: join(shots, `workbench-${w}.png`), fullPage: true });
  }
  // A segment of the toolpath, of a record other than the selected one, chosen by click and by keyboard:
  // its record's row and bytes are selected.
  const rowNow = async () => page.evaluate(() => {
    const row = document.querySelector('#records tr.wb-selected');
    return { row: row === null ? null : row.dataset.record, hex: document.getElementById('hex-title').textContent,
      segments: [...document.querySelectorAll('.wb-path path.wb-selected')].map((p) => p.dataset.record) };
  });
  const others = await page.evaluate(() => {
    const sel = document.querySelector('#records tr.wb-selected');
    const mine = sel === null ? null : sel.dataset.record;
    const recs = [...document.querySelectorAll('#path-top path[data-record]')].map((p) => p.dataset.record);
    return [...new Set(recs)].filter((r) => r !== mine).slice(0, 2);
  });
  if (others.length > 0) {
    await page.locator(`#path-top path[data-record="${others[0]}"]`).dispatchEvent('click');
    picked.push({ want: others[0], how: 'click', ...(await rowNow()) });
  }
  if (others.length > 1) {
    await page.focus(`#path-top path[data-record="${others[1]}"]`);
    await page.keyboard.press('Enter');
    picked.push({ want: others[1], how: 'keyboard', ...(await rowNow()) });
  }
  // The 3D view shares the selection: it shows the selected record; turned and zoomed by keyboard and
  // mouse; ] selects the next motion record, a click on a drawn segment its record.
  const view = () => page.evaluate(() => {
    const c = document.getElementById('path-3d');
    const row = document.querySelector('#records tr.wb-selected');
    return { ...c.dataset, row: row === null ? null : row.dataset.record };
  });
  three = { shared: await view() };
  await page.focus('#path-3d');
  for (const key of ['ArrowRight', 'ArrowUp', '+']) await page.keyboard.press(key);
  three.keyboard = await view();
  await page.keyboard.press(']');
  three.next = await view();
  await page.keyboard.press('0');
  const box = await page.locator('#path-3d').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 20, { steps: 4 });
  await page.mouse.up();
  await page.mouse.wheel(0, -200);
  three.mouse = await view();
  await page.keyboard.press('0');
  // a record other than the selected one whose segment's middle no other segment is drawn nearer to
  const aim = await page.evaluate(() => {
    const sel = document.getElementById('path-3d').dataset.selected;
    const recs = [...new Set([...document.querySelectorAll('#path-top path[data-record]')].map((p) => p.dataset.record))];
    for (const r of recs.filter((x) => x !== sel)) {
      const at = window.cbfWorkbench.where3d(Number(r));
      if (at !== null && String(window.cbfWorkbench.pick3d(at[0], at[1])) === r) return { want: r, at };
    }
    return null;
  });
  if (aim !== null) {
    await page.mouse.click(box.x + aim.at[0], box.y + aim.at[1]);
    three.clicked = { want: aim.want, ...(await view()) };
  }
}
await context.close();
process.stdout.write(`${JSON.stringify({ url, results, cuts, requests, errors, fetched, widths, selected, picked, paged, curve, three })}\n`);
