#!/usr/bin/env node
// Plays a glTF file in a real viewer: three.js (tools/npm) in headless
// Chromium (Debian's chromium), served from 127.0.0.1 by this script.
//   node sample.js FILE.glb --nodes a,b --times 0.5,1.5 [--shots 0.5,2.5 --png-dir DIR --width 960]
// Prints JSON: three.js's revision, the node names it loaded, each node's world
// pose [t, x, y, z, qx, qy, qz, qw] at each time; writes shot_<t>.png per shot.
// Exit 2 when chromium or three.js is missing, 1 when the page fails.
'use strict';
const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');
const { spawn } = require('child_process');

const THREE_DIR = path.join(__dirname, '..', 'npm', 'node_modules', 'three');
const CHROMIUM = process.env.TUMBLE_CHROMIUM || '/usr/bin/chromium';
const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json' };

function parse(argv) {
  const o = { nodes: '', times: '', shots: '', pngDir: '.', width: '960', file: null };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a === '--nodes') o.nodes = argv[++i];
    else if (a === '--times') o.times = argv[++i];
    else if (a === '--shots') o.shots = argv[++i];
    else if (a === '--png-dir') o.pngDir = argv[++i];
    else if (a === '--width') o.width = argv[++i];
    else o.file = a;
  }
  return o;
}

/// Serves /viewer.html, /three/... (the npm package) and /file/<name> (the file asked for).
function serve(file) {
  const routes = [['/three/', THREE_DIR], ['/file/', path.dirname(file)], ['/', __dirname]];
  return http.createServer((req, res) => {
    const url = decodeURIComponent(req.url.split('?')[0]);
    const [prefix, root] = routes.find(([p]) => url.startsWith(p));
    const target = path.normalize(path.join(root, url.slice(prefix.length)));
    if (!target.startsWith(root) || !fs.existsSync(target) || !fs.statSync(target).isFile()) {
      res.writeHead(404);
      return res.end();
    }
    res.writeHead(200, { 'Content-Type': TYPES[path.extname(target)] || 'application/octet-stream' });
    fs.createReadStream(target).pipe(res);
  });
}

function chromium(url, profile) {
  // The flags that work on a machine with no GPU and no network but loopback.
  const args = ['--headless', '--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
                '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
                '--disable-sync', '--user-data-dir=' + profile, '--virtual-time-budget=60000', '--dump-dom', url];
  return new Promise((resolve, reject) => {
    const p = spawn(CHROMIUM, args, { stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '', stderr = '';
    const timer = setTimeout(() => p.kill('SIGKILL'), 120000);
    p.stdout.on('data', (d) => (stdout += d));
    p.stderr.on('data', (d) => (stderr += d));
    p.on('error', reject);
    p.on('close', (code) => {
      clearTimeout(timer);
      resolve({ code, stdout, stderr });
    });
  });
}

async function main(o) {
  if (!o.file) throw new Error('usage: sample.js FILE.glb --nodes a,b --times t,... [--shots t,... --png-dir DIR]');
  if (!fs.existsSync(CHROMIUM)) return [2, 'sample.js: ' + CHROMIUM + ' is missing: run scripts/setup.sh test'];
  if (!fs.existsSync(path.join(THREE_DIR, 'package.json'))) return [2, 'sample.js: three.js is missing in tools/npm: run scripts/setup.sh test'];
  const file = path.resolve(o.file);
  const server = serve(file);
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'tumble-chromium-'));
  try {
    const q = new URLSearchParams({ file: '/file/' + path.basename(file), nodes: o.nodes, times: o.times, shots: o.shots, width: o.width });
    const run = await chromium('http://127.0.0.1:' + server.address().port + '/viewer.html?' + q, profile);
    const m = /<pre id="result">([\s\S]*?)<\/pre>/.exec(run.stdout);
    if (!m || !m[1]) return [1, 'sample.js: the page gave no result (chromium exited ' + run.code + ')\n' + run.stderr.slice(-2000)];
    const result = JSON.parse(m[1].replace(/&amp;/g, '&').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"'));
    if (result.error) return [1, 'sample.js: the page failed: ' + result.error];
    for (const [t, url] of Object.entries(result.shots)) {
      fs.mkdirSync(o.pngDir, { recursive: true });
      fs.writeFileSync(path.join(o.pngDir, 'shot_' + t + '.png'), Buffer.from(url.split(',')[1], 'base64'));
      result.shots[t] = path.join(o.pngDir, 'shot_' + t + '.png');
    }
    return [0, JSON.stringify(result)];
  } finally {
    server.close();
    fs.rmSync(profile, { recursive: true, force: true });
  }
}

main(parse(process.argv.slice(2))).then(([code, text]) => {
  (code ? console.error : console.log)(text);
  process.exit(code);
}, (e) => {
  console.error('sample.js: ' + e.stack);
  process.exit(1);
});
