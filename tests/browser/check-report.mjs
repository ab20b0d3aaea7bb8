#!/usr/bin/env node
// Browser check of one self-contained sealsim HTML report (inline CSS, inline <svg> charts,
// no scripts, no external fonts or images).
//
//   node check-report.mjs REPORT.html SCREENSHOT.png [--min-plots N] [--pdf FILE.pdf]
//
// Opens REPORT.html as a file:// URL in Debian's headless Chromium (/usr/bin/chromium, or
// $CHROMIUM) through playwright-core, and fails (exit 1, one "FAIL: ..." line per problem on
// stderr) on:
//   - any console message of type error or warning, any uncaught page error, a renderer crash;
//   - any request whose URL is neither the report's own file:// URL nor a data: URI (such
//     requests are also aborted, so nothing leaves the machine), and any failed request;
//   - fewer than N elements matching `figure.plot svg` (default N = 1);
//   - a `figure.plot svg` whose rendered box (boundingBox) is missing or has zero width/height;
//   - an <img>, <script>, <link rel=stylesheet>, SVG <image> or <use> pointing outside the
//     document (anything but a data: URI or a #fragment of the report itself).
// Whenever the page loaded it writes a full-page screenshot (viewport 1280 wide) to
// SCREENSHOT.png, also on failure so the failure can be looked at. On success it prints one
// JSON line: {"ok":true,"plots":N,"titles":[...],"requests":[...],"title":...,"height":...}.
// With --pdf it also prints the page as the print stylesheet lays it out (A4, Chromium's
// Page.printToPDF through page.pdf) to FILE.pdf, as an engineer files it with a design review
// (issue 42, item 7); shipped-reports.sh then checks what its first page says.
// Exit codes: 0 passed, 1 check failed, 2 usage error or the browser could not be started.
import { existsSync, statSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium } from './chromium.mjs';

const USAGE = 'usage: node check-report.mjs REPORT.html SCREENSHOT.png [--min-plots N] [--pdf FILE.pdf]';

function usage(msg) {
  console.error(`check-report: ${msg}\n${USAGE}`);
  process.exit(2);
}

// ---- arguments ---------------------------------------------------------------------------
const positional = [];
let minPlots = 1;
let pdfArg = null;
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i++) {
  const a = argv[i];
  let value = null;
  if (a === '--pdf') {
    if (i + 1 >= argv.length) usage('--pdf needs a file');
    pdfArg = argv[++i];
    continue;
  } else if (a === '--min-plots') {
    if (i + 1 >= argv.length) usage('--min-plots needs a value');
    value = argv[++i];
  } else if (a.startsWith('--min-plots=')) {
    value = a.slice('--min-plots='.length);
  } else if (a === '-h' || a === '--help') {
    console.log(USAGE);
    process.exit(0);
  } else if (a.startsWith('-')) {
    usage(`unknown option ${a}`);
  } else {
    positional.push(a);
    continue;
  }
  if (!/^\d+$/.test(value)) usage(`--min-plots wants a non-negative integer, got ${JSON.stringify(value)}`);
  minPlots = Number(value);
}
if (positional.length !== 2) usage('expected exactly REPORT.html and SCREENSHOT.png');
const [reportArg, screenshotArg] = positional;
const reportPath = resolve(reportArg);
const screenshotPath = resolve(screenshotArg);
if (!existsSync(reportPath) || !statSync(reportPath).isFile()) usage(`no such file: ${reportArg}`);

const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
if (!existsSync(executablePath)) usage(`no Chromium at ${executablePath} (check-report.sh installs Debian's)`);

// ---- URL policy --------------------------------------------------------------------------
const reportUrl = pathToFileURL(reportPath).href;

function withoutFragment(u) {
  try {
    const url = new URL(u);
    url.hash = '';
    return url.href;
  } catch {
    return u;
  }
}
const ownUrl = withoutFragment(reportUrl);

/** The only URLs a report may load: itself (any #fragment) and data: URIs. */
function allowed(u) {
  if (u.startsWith('data:')) return true;
  return withoutFragment(u) === ownUrl;
}

// ---- run ---------------------------------------------------------------------------------
const failures = [];
const fail = (msg) => failures.push(msg);
const requests = [];

const browser = await launchChromium(executablePath, 'check-report');

let summary = null;
try {
  const context = await browser.newContext({
    viewport: { width: 1280, height: 800 },
    deviceScaleFactor: 1,
    javaScriptEnabled: true, // so that a stray <script> shows up as console output, not silence
  });
  // Abort anything that is not the report itself or a data: URI, so nothing leaves the machine.
  await context.route((url) => !allowed(url.href), (route) => route.abort('blockedbyclient'));

  const page = await context.newPage();
  page.on('request', (req) => {
    requests.push(req.url());
    if (!allowed(req.url())) fail(`request outside the report: ${req.method()} ${req.url()}`);
  });
  page.on('requestfailed', (req) => {
    fail(`failed request: ${req.url()} (${req.failure()?.errorText ?? 'unknown error'})`);
  });
  page.on('console', (msg) => {
    const type = msg.type();
    if (type === 'error' || type === 'warning') {
      const loc = msg.location();
      const where = loc && loc.url ? ` at ${loc.url}:${loc.lineNumber}:${loc.columnNumber}` : '';
      fail(`console ${type}: ${msg.text()}${where}`);
    }
  });
  page.on('pageerror', (err) => fail(`page error: ${err.message}`));
  page.on('crash', () => fail('renderer crashed'));

  const response = await page.goto(reportUrl, { waitUntil: 'load', timeout: 30_000 });
  if (response && !response.ok() && response.status() !== 0) {
    fail(`loading the report gave status ${response.status()}`);
  }

  // Plots: every `figure.plot svg` must exist (at least minPlots) and be rendered with a size.
  const svgs = page.locator('figure.plot svg');
  const plots = await svgs.count();
  if (plots < minPlots) {
    fail(`found ${plots} element(s) matching "figure.plot svg", wanted at least ${minPlots}`);
  }
  for (let i = 0; i < plots; i++) {
    const box = await svgs.nth(i).boundingBox();
    const label = await svgs.nth(i).evaluate((el) => {
      const cap = el.closest('figure.plot')?.querySelector('figcaption');
      return cap ? cap.textContent.trim().replace(/\s+/g, ' ') : '(no figcaption)';
    });
    if (!box) fail(`plot svg #${i + 1} ("${label}") is not rendered (no bounding box)`);
    else if (!(box.width > 0) || !(box.height > 0)) {
      fail(`plot svg #${i + 1} ("${label}") renders as ${box.width}x${box.height}`);
    }
  }

  // Resources named in the DOM, loaded or not (a lazy <img> may not have been requested yet).
  const refs = await page.evaluate(() => {
    const out = [];
    const add = (el, attr, raw) => {
      if (raw == null || raw === '') return;
      let abs;
      try {
        abs = new URL(raw, document.baseURI).href;
      } catch {
        abs = raw;
      }
      out.push({ tag: el.tagName.toLowerCase(), attr, raw, abs });
    };
    for (const el of document.querySelectorAll('img')) {
      add(el, 'src', el.getAttribute('src'));
      const srcset = el.getAttribute('srcset');
      if (srcset) for (const part of srcset.split(',')) add(el, 'srcset', part.trim().split(/\s+/)[0]);
    }
    for (const el of document.querySelectorAll('script[src]')) add(el, 'src', el.getAttribute('src'));
    for (const el of document.querySelectorAll('link')) {
      const rel = (el.getAttribute('rel') || '').toLowerCase().split(/\s+/);
      if (rel.includes('stylesheet')) add(el, 'href', el.getAttribute('href'));
    }
    for (const el of document.querySelectorAll('image, use')) {
      add(el, 'href', el.getAttribute('href') ?? el.getAttribute('xlink:href'));
    }
    return out;
  });
  for (const r of refs) {
    if (!allowed(r.abs)) fail(`<${r.tag} ${r.attr}="${r.raw}"> points outside the document`);
  }
  // sealsim's reports carry no scripts at all
  const scripts = await page.evaluate(() => document.querySelectorAll('script').length);
  if (scripts > 0) fail(`${scripts} <script> element(s): a report has none`);

  const titles = await page
    .locator('figure.plot figcaption')
    .evaluateAll((els) => els.map((e) => e.textContent.trim().replace(/\s+/g, ' ')));
  const title = await page.title();
  const height = await page.evaluate(() =>
    Math.max(document.documentElement.scrollHeight, document.body ? document.body.scrollHeight : 0),
  );

  await page.screenshot({ path: screenshotPath, fullPage: true, timeout: 60_000 });
  summary = { ok: true, report: reportArg, plots, titles, requests, title, height, screenshot: screenshotArg };
  if (pdfArg) {
    // the report's own @page size (A4) and margins, backgrounds kept (the verdict's colour)
    await page.emulateMedia({ media: 'print' });
    await page.pdf({ path: resolve(pdfArg), preferCSSPageSize: true, printBackground: true, timeout: 60_000 });
    summary.pdf = pdfArg;
  }
} catch (e) {
  fail(`browser error: ${e.message.split('\n')[0]}`);
} finally {
  await browser.close().catch(() => {});
}

if (failures.length > 0) {
  for (const f of failures) console.error(`FAIL: ${f}`);
  console.error(`check-report: ${reportArg}: ${failures.length} problem(s)${summary ? `; screenshot in ${screenshotArg}` : ''}`);
  process.exit(1);
}
console.log(JSON.stringify(summary));
