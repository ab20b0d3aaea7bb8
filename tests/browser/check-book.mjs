#!/usr/bin/env node
// Browser check of pages of the built user guide (mdBook's HTML in target/book), the sibling of
// check-report.mjs for a multi-file site with scripts.
//
//   node check-book.mjs BOOK_DIR OUTDIR PAGE.html...
//
// Opens each PAGE (a path relative to BOOK_DIR) as a file:// URL in Debian's headless Chromium
// (/usr/bin/chromium, or $CHROMIUM) through playwright-core, waits for the load event and for the
// network to go idle, and fails (exit 1, one "FAIL: page: ..." line per problem on stderr) on:
//   - any console message of type error, any uncaught page error, a renderer crash;
//   - a failed request, a request outside BOOK_DIR (also aborted, so nothing leaves the machine;
//     data: URIs are allowed), and a page whose main text (`main`) is empty;
//   - a sidebar without links (mdBook 0.5 fills it from toc.js: no links means the script broke).
// Console warnings are printed ("warning: ...") but do not fail. Writes a screenshot
// OUTDIR/<page path with / as __>.png of each page (viewport 1280 × 800, not the full page).
// Prints one JSON line per page that passed. Exit codes: 0 passed, 1 check failed, 2 usage
// error or the browser could not be started.
import { existsSync, statSync } from 'node:fs';
import { resolve, sep } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium } from './chromium.mjs';

const USAGE = 'usage: node check-book.mjs BOOK_DIR OUTDIR PAGE.html...';
function usage(msg) {
  console.error(`check-book: ${msg}\n${USAGE}`);
  process.exit(2);
}

const argv = process.argv.slice(2);
if (argv.includes('-h') || argv.includes('--help')) {
  console.log(USAGE);
  process.exit(0);
}
if (argv.length < 3) usage('expected BOOK_DIR, OUTDIR and at least one page');
const [bookArg, outArg, ...pageArgs] = argv;
const bookDir = resolve(bookArg);
const outDir = resolve(outArg);
if (!existsSync(bookDir) || !statSync(bookDir).isDirectory()) usage(`no such directory: ${bookArg}`);
for (const p of pageArgs) {
  const full = resolve(bookDir, p);
  if (!existsSync(full) || !statSync(full).isFile()) usage(`no such page: ${p} (in ${bookArg})`);
}

const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
if (!existsSync(executablePath)) usage(`no Chromium at ${executablePath} (check-report.sh installs Debian's)`);

// Requests may go to the book's own files and data: URIs only.
const bookUrl = pathToFileURL(bookDir + sep).href;
function allowed(u) {
  return u.startsWith('data:') || u.startsWith(bookUrl);
}

const browser = await launchChromium(executablePath, 'check-book');

let failed = 0;
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  await context.route((url) => !allowed(url.href), (route) => route.abort('blockedbyclient'));
  for (const pageArg of pageArgs) {
    const failures = [];
    const fail = (msg) => failures.push(msg);
    const warnings = [];
    const requests = [];
    const page = await context.newPage();
    page.on('request', (req) => {
      requests.push(req.url());
      if (!allowed(req.url())) fail(`request outside the book: ${req.method()} ${req.url()}`);
    });
    page.on('requestfailed', (req) => {
      fail(`failed request: ${req.url()} (${req.failure()?.errorText ?? 'unknown error'})`);
    });
    page.on('console', (msg) => {
      const loc = msg.location();
      const where = loc && loc.url ? ` at ${loc.url}:${loc.lineNumber}:${loc.columnNumber}` : '';
      if (msg.type() === 'error') fail(`console error: ${msg.text()}${where}`);
      else if (msg.type() === 'warning') warnings.push(`${msg.text()}${where}`);
    });
    page.on('pageerror', (err) => fail(`page error: ${err.message}`));
    page.on('crash', () => fail('renderer crashed'));
    let summary = null;
    try {
      const url = pathToFileURL(resolve(bookDir, pageArg)).href;
      await page.goto(url, { waitUntil: 'load', timeout: 30_000 });
      await page.waitForLoadState('networkidle', { timeout: 15_000 }).catch(() => {});
      const title = await page.title();
      const mainText = await page.evaluate(() => (document.querySelector('main')?.innerText ?? '').trim().length);
      if (mainText === 0) fail('the page has no text in <main>');
      const sidebarLinks = await page.evaluate(() => document.querySelectorAll('#sidebar a[href], .sidebar a[href]').length);
      if (sidebarLinks === 0) fail('the sidebar has no links (toc.js did not run?)');
      const shot = resolve(outDir, `${pageArg.replaceAll('/', '__').replace(/\.html?$/, '')}.png`);
      await page.screenshot({ path: shot, timeout: 60_000 });
      summary = { ok: true, page: pageArg, title, main_chars: mainText, sidebar_links: sidebarLinks, requests: requests.length, screenshot: shot };
    } catch (e) {
      fail(`browser error: ${e.message.split('\n')[0]}`);
    }
    await page.close().catch(() => {});
    for (const w of warnings) console.error(`warning: ${pageArg}: console warning: ${w}`);
    if (failures.length > 0) {
      failed += 1;
      for (const f of failures) console.error(`FAIL: ${pageArg}: ${f}`);
    } else {
      console.log(JSON.stringify(summary));
    }
  }
} finally {
  await browser.close().catch(() => {});
}
if (failed > 0) {
  console.error(`check-book: ${failed} of ${pageArgs.length} page(s) failed`);
  process.exit(1);
}
