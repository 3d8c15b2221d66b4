// The npm packages live in tools/web/node_modules (one lock file for every web tool); Node's ESM
// resolution would not look there from tools/slides, so resolve them from tools/web explicitly.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';

const webRequire = createRequire(new URL('../web/package.json', import.meta.url));

async function load(name) {
  let resolved;
  try {
    resolved = webRequire.resolve(name);
  } catch {
    throw new Error(`npm package "${name}" is not installed: run npm ci --prefix tools/web`);
  }
  return import(pathToFileURL(resolved).href);
}

export const katex = (await load('katex')).default;
export const { Marked } = await load('marked');

// Folder of an installed package (for copying its CSS and fonts into the output).
export function webPackageDir(name) {
  const dir = fileURLToPath(new URL(`../web/node_modules/${name}/`, import.meta.url));
  if (!fs.existsSync(dir)) throw new Error(`npm package "${name}" is not installed: run npm ci --prefix tools/web`);
  return dir;
}
