// Firefox for the tests, driven over Marionette — Firefox's own remote protocol: JSON frames
// (`length:json`) on a TCP port — with nothing but Debian's firefox-esr: no npm package, no
// downloaded driver. Enough to open a page, run a script in it and take a screenshot.

import net from 'node:net';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawn } from 'node:child_process';

export const FIREFOX = process.env.FIREFOX || '/usr/bin/firefox-esr';

/** A free TCP port of 127.0.0.1. */
function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = /** @type {net.AddressInfo} */ (server.address());
      server.close(() => resolve(port));
    });
  });
}

/** Connects to `port`, retrying while Firefox starts. @param {number} port @param {number} ms */
async function connect(port, ms) {
  const until = Date.now() + ms;
  for (;;) {
    try {
      return await new Promise((resolve, reject) => {
        const socket = net.connect(port, '127.0.0.1', () => resolve(socket));
        socket.on('error', reject);
      });
    } catch (e) {
      if (Date.now() > until) throw new Error(`Firefox's Marionette did not answer on port ${port}: ${e}`);
      await new Promise((r) => setTimeout(r, 250));
    }
  }
}

/**
 * Headless Firefox with a fresh profile: `http:` and `https:` go to a proxy that does not exist
 * (so nothing leaves the machine), and a session is open.
 * @param {{ width: number, height: number }} size
 */
export async function launchFirefox({ width, height }) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'flexarm-firefox-'));
  const port = await freePort();
  const prefs = {
    'marionette.port': port,
    'browser.shell.checkDefaultBrowser': false,
    'browser.startup.homepage_override.mstone': 'ignore',
    'datareporting.policy.dataSubmissionEnabled': false,
    'toolkit.telemetry.reportingpolicy.firstRun': false,
    'app.update.disabledForTesting': true,
    'network.proxy.type': 1,
    'network.proxy.http': '127.0.0.1',
    'network.proxy.http_port': 9,
    'network.proxy.ssl': '127.0.0.1',
    'network.proxy.ssl_port': 9,
    'network.proxy.allow_hijacking_localhost': true,
  };
  fs.writeFileSync(path.join(profile, 'user.js'), Object.entries(prefs).map(([k, v]) => `user_pref(${JSON.stringify(k)}, ${JSON.stringify(v)});`).join('\n'));
  const child = spawn(FIREFOX, ['--headless', '--marionette', '--no-remote', '--profile', profile], { stdio: 'ignore' });
  const socket = /** @type {net.Socket} */ (await connect(port, 30000));

  // Frames in: `length:json`.
  let buffer = Buffer.alloc(0);
  /** @type {((frame: any) => void)[]} */
  const waiting = [];
  /** @type {any[]} */
  const frames = [];
  socket.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    for (;;) {
      const colon = buffer.indexOf(0x3a);
      if (colon < 0) break;
      const length = Number(buffer.subarray(0, colon).toString());
      if (buffer.length < colon + 1 + length) break;
      const frame = JSON.parse(buffer.subarray(colon + 1, colon + 1 + length).toString());
      buffer = buffer.subarray(colon + 1 + length);
      const next = waiting.shift();
      if (next) next(frame);
      else frames.push(frame);
    }
  });
  const nextFrame = () => new Promise((resolve) => (frames.length ? resolve(frames.shift()) : waiting.push(resolve)));
  await nextFrame(); // the greeting
  let id = 0;
  /** Sends a command and returns its result; throws its error. @param {string} name @param {object} [params] */
  const send = async (name, params = {}) => {
    const body = Buffer.from(JSON.stringify([0, ++id, name, params]));
    socket.write(`${body.length}:`);
    socket.write(body);
    const [, , error, result] = await nextFrame();
    if (error) throw new Error(`${name}: ${error.error}: ${error.message}`);
    return result;
  };
  await send('WebDriver:NewSession', { capabilities: { alwaysMatch: { acceptInsecureCerts: true } } });
  await send('WebDriver:SetWindowRect', { width, height });
  return {
    /** @param {string} url */
    navigate: (url) => send('WebDriver:Navigate', { url }),
    /** Runs `script` (a function body) in the page and returns its value. @param {string} script */
    evaluate: async (script) => (await send('WebDriver:ExecuteScript', { script, args: [] })).value,
    /** A PNG of the viewport. */
    screenshot: async () => Buffer.from((await send('WebDriver:TakeScreenshot', { full: false })).value, 'base64'),
    close: async () => {
      await send('Marionette:Quit').catch(() => {});
      socket.destroy();
      await new Promise((r) => (child.exitCode === null ? child.on('exit', r) : r(null)));
      fs.rmSync(profile, { recursive: true, force: true });
    },
  };
}
