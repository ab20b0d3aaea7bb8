// Debian's headless Chromium through playwright-core, started the one way both browser checks
// (check-report.mjs, check-book.mjs) need: as root, no GPU, and none of Chromium's own
// connections, which this closed network refuses. A start that fails exits with status 2,
// the message led by `tag`.
import { chromium } from 'playwright-core';

export async function launchChromium(executablePath, tag) {
  try {
    return await chromium.launch({
      executablePath,
      timeout: 60_000,
      args: [
        '--headless',
        '--no-sandbox', // we run as root
        '--disable-gpu',
        // Without these Chromium opens connections of its own, which this closed network refuses.
        '--disable-quic',
        '--no-first-run',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
      ],
    });
  } catch (e) {
    console.error(`${tag}: could not start Chromium at ${executablePath}: ${e.message}`);
    process.exit(2);
  }
}
