#!/usr/bin/env node
// Validates glTF files with the Khronos glTF-Validator (npm gltf-validator,
// installed in tools/npm by scripts/setup.sh test). Prints one line per file
// (errors, warnings, infos and the first messages); --json FILE writes the
// full reports. Exit 1 when any file has an error, 2 when the validator is missing.
'use strict';
const fs = require('fs');
const path = require('path');

let validator;
try {
  validator = require(path.join(__dirname, 'npm', 'node_modules', 'gltf-validator'));
} catch (e) {
  console.error('validate_gltf: gltf-validator is not installed: run scripts/setup.sh test (' + e.message + ')');
  process.exit(2);
}

async function main(args) {
  let jsonOut = null;
  const files = [];
  for (let i = 0; i < args.length; ++i) {
    if (args[i] === '--json') jsonOut = args[++i];
    else files.push(args[i]);
  }
  if (!files.length) {
    console.error('usage: validate_gltf.js [--json REPORT] FILE.glb|FILE.gltf ...');
    return 2;
  }
  const reports = [];
  let failed = 0;
  for (const f of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(f)), {
      uri: path.basename(f),
      maxIssues: 100,
      externalResourceFunction: (uri) => Promise.reject(new Error('external resource ' + uri + ' (tumble embeds all)')),
    });
    const n = report.issues;
    if (n.numErrors > 0) failed++;
    const first = n.messages.filter((m) => m.severity <= 1).slice(0, 3).map((m) => m.code + ' ' + m.pointer + ': ' + m.message);
    console.log(`${f}: ${n.numErrors} errors, ${n.numWarnings} warnings, ${n.numInfos} infos` +
                (first.length ? ' | ' + first.join(' | ') : ''));
    reports.push(report);
  }
  if (jsonOut) fs.writeFileSync(jsonOut, JSON.stringify(reports, null, 2));
  console.log(`validator ${reports[0].validatorVersion}: ${files.length} files, ${failed} with errors`);
  return failed ? 1 : 0;
}

main(process.argv.slice(2)).then((rc) => process.exit(rc), (e) => {
  console.error('validate_gltf: ' + e.stack);
  process.exit(1);
});
