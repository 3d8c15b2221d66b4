// The browser build's pages over HTTP on 127.0.0.1 (a page cannot load its .wasm and .data from
// file://): make serve, and the web tests and benchmark, which ask for a free port (0).
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

// The decks' stylesheets and fonts too: a browser ignores a stylesheet served as anything but
// text/css (the decks then showed every slide at once, unstyled).
const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
                '.data': 'application/octet-stream', '.md': 'text/plain; charset=utf-8', '.png': 'image/png',
                '.css': 'text/css', '.woff2': 'font/woff2', '.woff': 'font/woff', '.ttf': 'font/ttf',
                '.svg': 'image/svg+xml', '.pdf': 'application/pdf', '.json': 'application/json' };

// Resolves to the listening server; server.address().port is the port.
export async function serveSite(dir, port = 0) {
  const root = path.resolve(dir);
  const server = http.createServer((req, res) => {
    let file = path.join(root, decodeURIComponent(new URL(req.url, 'http://x').pathname));
    if (!file.startsWith(root)) return res.writeHead(403).end();
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, body) => {
      if (err) return res.writeHead(404).end('not found');
      res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' }).end(body);
    });
  });
  await new Promise((resolve) => server.listen(port, '127.0.0.1', resolve));
  return server;
}
