// serve.mjs DIR [PORT]: the browser build's pages on http://127.0.0.1:PORT/ (make serve). Any static
// web server does the same: the folder is plain files (the .wasm served as application/wasm).
import fs from 'node:fs';
import path from 'node:path';
import { serveSite } from './site_server.mjs';

const root = path.resolve(process.argv[2] || 'build/web/site');
const port = Number(process.argv[3] || process.env.PORT || 8000);
if (!fs.existsSync(path.join(root, 'index.html'))) {
  console.error(`serve: ${root}/index.html missing; make web builds the pages`);
  process.exit(1);
}
await serveSite(root, port);
console.log(`shadowlab in the browser: http://127.0.0.1:${port}/  (Ctrl+C stops)`);
