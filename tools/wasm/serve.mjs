// serve.mjs DIR [PORT]: the browser build's pages on http://127.0.0.1:PORT/ (make serve). Any static
// web server does the same: the folder is plain files (the .wasm served as application/wasm).
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

const root = path.resolve(process.argv[2] || 'build/web/site');
const port = Number(process.argv[3] || process.env.PORT || 8000);
if (!fs.existsSync(path.join(root, 'index.html'))) {
  console.error(`serve: ${root}/index.html missing; make web builds the pages`);
  process.exit(1);
}
const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
                '.data': 'application/octet-stream', '.md': 'text/plain; charset=utf-8', '.png': 'image/png' };
http.createServer((req, res) => {
  let file = path.join(root, decodeURIComponent(new URL(req.url, 'http://x').pathname));
  if (!file.startsWith(root)) return res.writeHead(403).end();
  if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
  fs.readFile(file, (err, body) => {
    if (err) return res.writeHead(404).end('not found');
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' }).end(body);
  });
}).listen(port, '127.0.0.1', () => console.log(`shadowlab in the browser: http://127.0.0.1:${port}/  (Ctrl+C stops)`));
