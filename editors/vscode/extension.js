// The OpenRAPID extension: starts `rapid lsp` for RAPID files and runs `rapid dap` for
// debug sessions of type `rapid`. Plain JavaScript, so the extension needs no build step.
'use strict';
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

// The `rapid` command from the settings.
function rapidPath() {
  return vscode.workspace.getConfiguration('rapid').get('path') || 'rapid';
}

async function startServer(context) {
  if (!vscode.workspace.getConfiguration('rapid').get('lsp.enable')) return;
  const command = rapidPath();
  client = new LanguageClient(
    'rapid',
    'RAPID (rapid lsp)',
    { run: { command, args: ['lsp'] }, debug: { command, args: ['lsp'] } },
    { documentSelector: [{ scheme: 'file', language: 'rapid' }] },
  );
  await client.start();
  context.subscriptions.push(client);
}

// The debug adapter is `rapid dap` over stdio.
class AdapterFactory {
  createDebugAdapterDescriptor() {
    return new vscode.DebugAdapterExecutable(rapidPath(), ['dap']);
  }
}

// A pendant dialog waits: ask the user and hand the answer to the adapter
// (its custom request `rapidAnswer`; `:answer TEXT` in the debug console does the same).
async function answerPrompt() {
  const session = vscode.debug.activeDebugSession;
  if (!session || session.type !== 'rapid') {
    vscode.window.showWarningMessage('No RAPID debug session is active.');
    return;
  }
  const text = await vscode.window.showInputBox({ prompt: 'Answer to the pendant dialog' });
  if (text === undefined) return;
  try {
    await session.customRequest('rapidAnswer', { text });
  } catch (e) {
    vscode.window.showErrorMessage(`RAPID: ${e.message || e}`);
  }
}

async function activate(context) {
  context.subscriptions.push(
    vscode.debug.registerDebugAdapterDescriptorFactory('rapid', new AdapterFactory()),
    vscode.commands.registerCommand('rapid.answerPrompt', answerPrompt),
    vscode.commands.registerCommand('rapid.restartServer', async () => {
      if (client) await client.stop();
      client = undefined;
      await startServer(context);
    }),
  );
  await startServer(context);
}

async function deactivate() {
  if (client) await client.stop();
}

module.exports = { activate, deactivate };
