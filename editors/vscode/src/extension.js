'use strict';
// The client of the GMacDSL language server: starts `gmac lsp` over standard input and output for
// .gmac documents. Colours, brackets, folding and snippets come from the declarative parts of the
// extension (package.json) and work without the server.

const vscode = require('vscode');
const { serverCommand, commandExists, initializationOptions } = require('./server-command');

let client;
let output;
let watcher;
let starting;

function settings() {
  const config = vscode.workspace.getConfiguration('gmac');
  const folder = vscode.workspace.workspaceFolders?.[0]?.uri.fsPath;
  return {
    enable: config.get('enableServer', true),
    serverPath: config.get('serverPath', ''),
    serverArgs: config.get('serverArgs', ['lsp']),
    dslFolders: config.get('dslFolders', []),
    standardLibrary: config.get('standardLibrary', false),
    workspaceFolder: folder,
  };
}

async function start() {
  const s = settings();
  if (!s.enable) {
    output.appendLine('gmac.enableServer is false: the language server is not started.');
    return;
  }
  const { LanguageClient, State, CloseAction, ErrorAction } = require('vscode-languageclient/node');
  const command = serverCommand(s);
  let ran = false; // the server answered initialize
  output.appendLine(`Starting ${[command.command, ...command.args].join(' ')}${s.workspaceFolder ? ` in ${s.workspaceFolder}` : ''}`);
  if (!commandExists(command.command)) {
    // Checked here: vscode-languageclient shows an error of its own for a command that cannot be spawned.
    reportStartFailure(command, new Error(`${command.command} is not an executable file or a command on the PATH`));
    return;
  }

  // Standard input and output, with no transport named: TransportKind.stdio would append --stdio
  // to the arguments, and the server is started exactly as `gmac lsp`.
  const serverOptions = {
    command: command.command,
    args: command.args,
    options: s.workspaceFolder ? { cwd: s.workspaceFolder } : {},
  };
  const clientOptions = {
    documentSelector: [
      { scheme: 'file', language: 'gmac' },
      { scheme: 'untitled', language: 'gmac' },
    ],
    synchronize: {
      fileEvents: watcher,
    },
    initializationOptions: initializationOptions(s),
    outputChannel: output,
    // A failed start is reported once, below, instead of the library's own message and retries.
    initializationFailedHandler: (error) => {
      output.appendLine(`initialize failed: ${error?.message ?? error}`);
      return false;
    },
    errorHandler: errorHandler(),
  };
  client = new LanguageClient('gmac', 'GMacDSL Language Server', serverOptions, clientOptions);
  client.onDidChangeState((event) => {
    if (event.newState === State.Running) ran = true;
  });

  function errorHandler() {
    let restarts = [];
    return {
      error: (_error, _message, count) => ({ action: count && count <= 3 ? ErrorAction.Continue : ErrorAction.Shutdown }),
      closed: () => {
        // A server that never answered initialize is not restarted: the start failure says why.
        if (!ran) return { action: CloseAction.DoNotRestart, handled: true };
        const now = Date.now();
        restarts = [...restarts.filter((t) => now - t < 3 * 60 * 1000), now];
        if (restarts.length <= 4) {
          output.appendLine('gmac lsp stopped; restarting it.');
          return { action: CloseAction.Restart, handled: true };
        }
        return {
          action: CloseAction.DoNotRestart,
          message: "GMacDSL: gmac lsp stopped 5 times in 3 minutes and is not restarted; see the GMacDSL output, then run 'GMacDSL: Restart Language Server'.",
        };
      },
    };
  }
  try {
    await client.start();
  } catch (error) {
    const failed = client;
    client = undefined;
    try { await failed.dispose(); } catch { /* it never ran */ }
    // vscode-languageclient has already shown its error (with a button to this output): say here
    // what to do, without a second notification.
    reportStartFailure(command, error, false);
  }
}

function reportStartFailure(command, error, notify = true) {
  const line = [command.command, ...command.args].join(' ');
  output.appendLine(`Could not start '${line}': ${error?.message ?? error}`);
  output.appendLine("Colours and snippets work without the server; diagnostics and hover need gmac lsp. Set 'gmac.serverPath' "
    + "(and 'gmac.serverArgs') to a gmac that has the lsp command, or set 'gmac.enableServer' to false.");
  if (!notify) return;
  const message = `GMacDSL: could not start the language server ('${line}'). Colours and snippets still work; `
    + "diagnostics and hover need gmac lsp. Set 'gmac.serverPath' to a gmac that has the lsp command, or turn the server off.";
  vscode.window.showWarningMessage(message, 'Open Settings', 'Turn Off', 'Show Output').then((choice) => {
    if (choice === 'Open Settings') vscode.commands.executeCommand('workbench.action.openSettings', '@ext:gmac.gmac');
    else if (choice === 'Turn Off') vscode.workspace.getConfiguration('gmac').update('enableServer', false, vscode.ConfigurationTarget.Global);
    else if (choice === 'Show Output') output.show(true);
  });
}

async function stop() {
  const running = client;
  client = undefined;
  if (running) await running.stop().catch(() => undefined);
}

function restart() {
  // One start at a time: settings changed twice in a row restart once after the other.
  starting = (starting ?? Promise.resolve()).then(stop).then(start).catch((error) => {
    output.appendLine(`Restart failed: ${error?.message ?? error}`);
  });
  return starting;
}

function activate(context) {
  // A log channel: vscode-languageclient writes to it with info(), warn(), error() and trace().
  output = vscode.window.createOutputChannel('GMacDSL', { log: true });
  watcher = vscode.workspace.createFileSystemWatcher('**/*.gmac');
  context.subscriptions.push(
    output,
    watcher,
    vscode.commands.registerCommand('gmac.restartServer', restart),
    vscode.commands.registerCommand('gmac.showOutput', () => output.show(true)),
    vscode.workspace.onDidChangeConfiguration((event) => {
      const affects = ['gmac.enableServer', 'gmac.serverPath', 'gmac.serverArgs', 'gmac.dslFolders', 'gmac.standardLibrary']
        .some((section) => event.affectsConfiguration(section));
      if (affects) restart();
    }),
  );
  // Not awaited: the editor does not wait for the server, which may take seconds to come up.
  void restart();
}

function deactivate() {
  return stop();
}

module.exports = { activate, deactivate };
