// The native `grape` tool, run as a user would, for the values the WebAssembly build must
// reproduce. GRAPE_TOOL names the binary (default: build/apps/grape/grape of this checkout).
'use strict';
const { execFileSync } = require('child_process');
const path = require('path');
const fs = require('fs');

const tool = process.env.GRAPE_TOOL || path.join(__dirname, '..', '..', 'build', 'apps', 'grape', 'grape');
if (!fs.existsSync(tool)) throw new Error(`native grape tool not found at ${tool} (build grape_tool or set GRAPE_TOOL)`);

/** The tool's JSON answer to `grape ...args`. */
function grape(...args) {
  return JSON.parse(execFileSync(tool, args.map(String), { encoding: 'utf8' }));
}

/** |a − b| in units in the last place of the larger (0 when bit-identical, NaN never equal). */
function ulpDistance(a, b) {
  if (Object.is(a, b)) return 0;
  const ulp = Math.max(Math.abs(a), Math.abs(b)) * Number.EPSILON;
  return Math.abs(a - b) / ulp;
}

module.exports = { grape, ulpDistance, tool };
