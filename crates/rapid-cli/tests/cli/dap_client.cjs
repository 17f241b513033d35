// A whole `rapid dap` session driven by the real DAP client library of VS Code's
// adapter tests (@vscode/debugadapter-testsupport): launch, a breakpoint hit with its
// file:line, threads, variables with a record expanded, setVariable (module data and a
// routine's data), evaluate (with a built-in call), exception filters, step
// in/over/out and back, continue, the pendant's output, the end.
// Usage: node dap_client.cjs RAPID PROJECT (the library comes from NODE_PATH).
'use strict';
const assert = require('assert');
const fs = require('fs');
const path = require('path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const [rapid, project] = process.argv.slice(2);
const modFile = path.join(project, 'rob', 'MainModule.mod');
const text = fs.readFileSync(modFile, 'utf8');
const lineOf = (needle) => text.split('\n').findIndex((l) => l.includes(needle)) + 1;

async function main() {
  const dc = new DebugClient(rapid, 'dap', 'rapid');
  dc.defaultTimeout = 20000;
  const output = [];
  dc.on('output', (e) => output.push(e.body.output));
  await dc.start();
  try {
    await session(dc, output);
  } finally {
    await dc.stop();
  }
}

async function stoppedAt(dc, request, line, routine) {
  await Promise.all([request, dc.waitForEvent('stopped')]);
  const trace = await dc.stackTraceRequest({ threadId: 1 });
  const top = trace.body.stackFrames[0];
  assert.strictEqual(top.line, line, `stopped at line ${top.line}, expected ${line}`);
  if (routine) assert.strictEqual(top.name, routine);
  return top.id;
}

async function evaluate(dc, frameId, expression) {
  const r = await dc.evaluateRequest({ expression, frameId, context: 'watch' });
  return r.body.result;
}

async function session(dc, output) {
  const atCall = lineOf('Helper 5;');
  const launch = { program: project, tpInput: path.join(project, 'answers.txt') };
  await dc.hitBreakpoint(launch, { path: modFile, line: atCall });

  const threads = await dc.threadsRequest();
  assert.deepStrictEqual(threads.body.threads.map((t) => t.name), ['T_ROB1', 'T_OTHER']);

  const trace = await dc.stackTraceRequest({ threadId: 1 });
  const frame = trace.body.stackFrames[0];
  assert.strictEqual(frame.source.path, fs.realpathSync(modFile));
  const scopes = await dc.scopesRequest({ frameId: frame.id });
  assert.deepStrictEqual(scopes.body.scopes.map((s) => s.name), ['Locals', 'Module data', 'Persistents']);
  const data = scopes.body.scopes[1].variablesReference;
  let vars = (await dc.variablesRequest({ variablesReference: data })).body.variables;
  assert.strictEqual(vars.find((v) => v.name === 'count').value, '1');
  const item = vars.find((v) => v.name === 'item');
  assert.strictEqual(item.type, 'part');
  const parts = (await dc.variablesRequest({ variablesReference: item.variablesReference })).body.variables;
  assert.deepStrictEqual(parts.map((p) => [p.name, p.value, p.type]), [['id', '7', 'num'], ['label', '"bolt"', 'string']]);

  const set = await dc.setVariableRequest({ variablesReference: data, name: 'count', value: '41' });
  assert.strictEqual(set.body.value, '41');
  assert.strictEqual(await evaluate(dc, frame.id, 'count + item.id'), '48');

  let top = await stoppedAt(dc, dc.stepInRequest({ threadId: 1 }), lineOf('twice := n * 2;'), 'Helper');
  assert.strictEqual(await evaluate(dc, top, 'n * 2 + count'), '51');
  // A routine's data is written in its frame (the next statement assigns it anew);
  // a built-in function without side effects is evaluated: |-41| = 41.
  const locals = (await dc.scopesRequest({ frameId: top })).body.scopes[0].variablesReference;
  const twice = await dc.setVariableRequest({ variablesReference: locals, name: 'twice', value: '3' });
  assert.strictEqual(twice.body.value, '3');
  assert.strictEqual(await evaluate(dc, top, 'twice + Abs(-count)'), '44');
  const filters = await dc.setExceptionBreakpointsRequest({ filters: ['raised', 'uncaught'] });
  assert.strictEqual(filters.success, true);
  await stoppedAt(dc, dc.nextRequest({ threadId: 1 }), lineOf('count := count + twice;'));
  top = await stoppedAt(dc, dc.stepOutRequest({ threadId: 1 }), lineOf('count := count + 1;'), 'main');
  assert.strictEqual(await evaluate(dc, top, 'count'), '51');
  await stoppedAt(dc, dc.nextRequest({ threadId: 1 }), lineOf('TPWrite'));
  await stoppedAt(dc, dc.nextRequest({ threadId: 1 }), lineOf('Bump;'));
  assert.ok(output.includes('count 52\n'), `TPWrite's line as an output event: ${JSON.stringify(output)}`);
  top = await stoppedAt(dc, dc.nextRequest({ threadId: 1 }), lineOf('total := count;'));
  assert.strictEqual(await evaluate(dc, top, 'count'), '152');
  // Back over the call of Bump: its BACKWARD handler runs.
  top = await stoppedAt(dc, dc.stepBackRequest({ threadId: 1 }), lineOf('Bump;'));
  assert.strictEqual(await evaluate(dc, top, 'count'), '52');

  await Promise.all([dc.continueRequest({ threadId: 1 }), dc.waitForEvent('terminated')]);
  // T_OTHER's dialog was answered from tpInput, and its line came out.
  assert.ok(output.includes('speed 25\n'), `T_OTHER's lines: ${JSON.stringify(output)}`);
  console.log('dap session passed');
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
