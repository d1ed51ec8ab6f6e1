import { chromium } from 'playwright-core';
import { serve, SIZES } from './harness.mjs';
const srv = await serve();
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'] });
const states = (process.env.STATES || 'pf=off&mode=full').split(' ');
const size = process.env.SIZE || 'laptop';
for (const [i, st] of states.entries()) {
  const page = await browser.newPage(SIZES[size]);
  page.on('pageerror', (e) => console.log('PAGEERROR', e.message));
  await page.goto(`${srv.base}/?${st}`);
  await page.waitForFunction(() => document.querySelector('[data-live="a4"]')?.textContent !== '—', null, { timeout: 60000 });
  await page.evaluate(() => { document.getElementById('explain').open = true; });
  await page.waitForTimeout(1500);
  const live = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('[data-live]')].map((n) => [n.dataset.live, n.textContent])));
  if (process.env.DUMP) console.log(st, JSON.stringify(live, null, 1));
  const sel = process.env.SEL || '#explain';
  const el = await page.$(sel);
  await el.screenshot({ path: `/tmp/s37/${size}-${i}.png` });
  if (process.env.TEXT) console.log((await el.innerText()).slice(0, 20000));
  await page.close();
}
await browser.close(); await srv.close();
