// A session driven by VS Code's own test client (@vscode/debugadapter-testsupport's DebugClient):
// node vscode_client.js PYTHON FOLDER.  test_hostile.py runs it when node finds the package.
"use strict";
const assert = require("assert");
const fs = require("fs");
const path = require("path");
const { DebugClient } = require("@vscode/debugadapter-testsupport");

const [python, folder] = process.argv.slice(2);
const job = path.join(folder, "job.nc");
fs.writeFileSync(job, 'logmsg "first"\n#1 = 1\nlogmsg "second"\n#2 = 2\nGoSub here\nM30\nSub here\n  #3 = 3\nEndSub\n');

async function main() {
  const dc = new DebugClient(JSON.stringify(python) + " -m edingcnc_lang", "debug", "ecnc", { shell: true });
  dc.defaultTimeout = 60000;
  await dc.start();
  try {
    await dc.hitBreakpoint({ program: job, cwd: folder, logDir: folder }, { path: job, line: 4 });
    const placed = await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: "here" }] });
    assert.strictEqual(placed.body.breakpoints[0].line, 7);
    await assert.rejects(dc.setVariableRequest({ variablesReference: 3, name: "#-620", value: "0" }), /is not a parameter/);
    await assert.rejects(dc.setVariableRequest({ variablesReference: 3, name: "#5380", value: "0" }), /read-only/);
    await assert.rejects(dc.setVariableRequest({ variablesReference: 1, name: "#1", value: "[1" }), /#1|\[/);
    await assert.rejects(dc.configurationDoneRequest(), /sent already/);
    await assert.rejects(dc.customRequest("continue", "threadId=1"), /arguments must be an object/);
    await assert.rejects(dc.evaluateRequest({ expression: ["#1"] }), /expression must be a string/);
    await Promise.all([dc.stepBackRequest({ threadId: 1 }), dc.assertStoppedLocation("step", { line: 3 })]);
    await Promise.all([dc.stepBackRequest({ threadId: 1 }), dc.assertStoppedLocation("step", { path: job, line: 2 })]);
    await Promise.all([dc.continueRequest({ threadId: 1 }), dc.assertStoppedLocation("breakpoint", { line: 4 })]);
    await Promise.all([dc.continueRequest({ threadId: 1 }),
                       dc.assertStoppedLocation("function breakpoint", { line: 8 })]);
    await Promise.all([dc.continueRequest({ threadId: 1 }), dc.waitForEvent("terminated")]);
    assert.strictEqual(fs.readFileSync(path.join(folder, "log.txt"), "utf8"), "first\nsecond\n");
  } finally {
    await dc.stop();
  }
}

main().then(() => console.log("ok"), (err) => { console.error(err); process.exit(1); });
