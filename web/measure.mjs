// Frame times of the demo pages in headless chromium (Debian's; software WebGL through
// SwiftShader, so the drawing is far slower than on a laptop's GPU): for each page and mode,
// after 5 s, the HUD's mean frame time, the page's own work per frame and, for the broadphase,
// collide's two calls per frame. A measurement, not a test.
//   npm run build && node measure.mjs
import { chromium } from 'playwright-core';
import { startServer } from './serve.mjs';

const { server, url } = await startServer({ port: 0 });
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
});
const page = await browser.newPage({ viewport: { width: 1280, height: 760 } });
const broad = (structure, count) => [['check', 'input[name=mode][value="broad"]'], ['select', '#structure', structure], ['select', '#count', count]];
const cases = [
  ['explorer 2D', 'explorer/', []],
  ['explorer 3D', 'explorer/', [['check', 'input[name=mode][value="3d"]']]],
  ['bounds3d tests', 'bounds3d/', []],
  ['bounds3d broadphase grid 3000', 'bounds3d/', broad('grid', '3000')],
  ['bounds3d broadphase tree 3000', 'bounds3d/', broad('tree', '3000')],
  ['bounds3d broadphase grid 5000', 'bounds3d/', broad('grid', '5000')],
  ['scroller', 'scroller/', []],
  ['slingshot', 'slingshot/', []],
];
console.log('| page | frame ms | work ms | collide ms | objects |\n|---|---|---|---|---|');
for (const [name, path, actions] of cases) {
  await page.goto(url + path);
  await page.waitForFunction(() => window.__demo?.ready);
  for (const [kind, selector, value] of actions) {
    if (kind === 'check') await page.check(selector);
    else await page.selectOption(selector, value);
  }
  await page.waitForTimeout(5000);
  const h = await page.evaluate(() => window.__demo.hud);
  const panel = await page.locator('#panel').innerText().catch(() => '');
  const collide = /collide per frame\s+([\d.]+) ms/.exec(panel)?.[1] ?? '';
  console.log(`| ${name} | ${h.frameMs.toFixed(1)} | ${h.workMs.toFixed(2)} | ${collide} | ${h.objects} |`);
}
await browser.close();
server.close();
