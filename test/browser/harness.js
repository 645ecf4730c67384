// What the replay page's browser tests share: the page named on the
// command line, Debian's Chromium through playwright-core, and the checks'
// bookkeeping. A test script calls run(usage, body[, pageOptions]): body
// gets a new page (1200 by 800; pageOptions are more of playwright's
// newPage options, e.g. { hasTouch: true }), the console errors the page
// has met so far, and a function that loads the page file and waits for
// window.afrpReplay. run exits 0 when every check passed, 1 with the
// failures listed otherwise, 2 when the page or Chromium is missing.
// Chromium: $CHROMIUM, else /usr/bin/chromium (Debian: apt-get install chromium).
'use strict';
const path = require('path');
const fs = require('fs');
const { chromium } = require('playwright-core');

const failures = [];
function check(ok, what) { console.log((ok ? 'ok   ' : 'FAIL ') + what); if (!ok) failures.push(what); }
function near(a, b, tol) { return a.every((v, i) => Math.abs(v - b[i]) <= tol); }

function run(usage, body, pageOptions) {
  const pagePath = process.argv[2];
  if (!pagePath) { console.error('usage: ' + usage); process.exit(2); }
  const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
  if (!fs.existsSync(executablePath)) {
    console.error('no Chromium at ' + executablePath + ' (on Debian: apt-get install -y chromium; or set CHROMIUM)');
    process.exit(2);
  }
  (async () => {
    const browser = await chromium.launch({ executablePath, headless: true, args: ['--no-sandbox'] });
    try {
      const page = await browser.newPage(Object.assign({ viewport: { width: 1200, height: 800 } }, pageOptions || {}));
      const errors = [];
      page.on('console', m => { if (m.type() === 'error') errors.push(m.type() + ': ' + m.text()); });
      page.on('pageerror', e => errors.push('page error: ' + e.message));
      await body(page, errors, () => page.goto('file://' + path.resolve(pagePath))
        .then(() => page.waitForFunction(() => window.afrpReplay !== undefined, null, { timeout: 10000 })));
    } finally {
      await browser.close();
    }
    if (failures.length) { console.error(failures.length + ' check(s) failed'); process.exit(1); }
    console.log('all checks passed');
  })().catch(e => { console.error(e && e.stack || String(e)); process.exit(1); });
}

module.exports = { run, check, near };
