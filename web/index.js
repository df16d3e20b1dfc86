// grape for JavaScript (CommonJS, Node): `const grape = await require('grape-wasm')();`
// Loads the WebAssembly build from dist/ (made by `scripts/build-web`). The wasm bytes are
// passed in directly: emscripten 3.1.6 would fetch() a file path, which Node's fetch refuses.
'use strict';
const fs = require('fs');
const path = require('path');
const createGrape = require('./dist/grape-node.js');

module.exports = function loadGrape(options = {}) {
  const wasmBinary = fs.readFileSync(path.join(__dirname, 'dist', 'grape-node.wasm'));
  return createGrape({ wasmBinary, ...options });
};
module.exports.default = module.exports;
