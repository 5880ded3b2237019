'use strict';
// src/extension.js under node with a stand-in for the vscode module: it starts the configured
// server over stdio, sends initialize with the DSL settings, stops it on deactivate, and reports a
// server that cannot start once, without retrying.
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { createStub, installStub } = require('./vscode-stub');

const fakeServer = path.join(__dirname, 'fixtures', 'fake-server.js');

function freshExtension() {
  for (const key of Object.keys(require.cache)) {
    if (key.includes(`${path.sep}src${path.sep}`) || key.includes('vscode-languageclient')) delete require.cache[key];
  }
  return require('../src/extension');
}

async function until(condition, what, ms = 10000) {
  const start = Date.now();
  while (!condition()) {
    if (Date.now() - start > ms) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 25));
  }
}

const readLog = (file) => (fs.existsSync(file) ? fs.readFileSync(file, 'utf8').trim().split('\n').filter(Boolean).map((l) => JSON.parse(l)) : []);

test('the client starts gmac.serverPath with gmac.serverArgs over stdio and initializes it with the DSL settings', async () => {
  const workspace = fs.mkdtempSync(path.join(os.tmpdir(), 'gmac-ws-'));
  const log = path.join(workspace, 'server.log');
  const { vscode, shown, fireConfigurationChange } = createStub({
    workspaceFolder: workspace,
    settings: {
      'gmac.serverPath': process.execPath,
      'gmac.serverArgs': [fakeServer, log, 'lsp'],
      'gmac.dslFolders': ['dsl'],
      'gmac.standardLibrary': true,
    },
  });
  const uninstall = installStub(vscode);
  try {
    const extension = freshExtension();
    const context = { subscriptions: [] };
    extension.activate(context);
    await until(() => readLog(log).some((m) => m.method === 'initialized'), 'initialized');
    const [started, initialize] = readLog(log);
    assert.equal(fs.realpathSync(started.cwd), fs.realpathSync(workspace), 'started in the workspace folder');
    assert.deepEqual(started.args, ['lsp']);
    assert.equal(initialize.method, 'initialize');
    assert.deepEqual(initialize.params.initializationOptions, { dslFolders: [path.join(workspace, 'dsl')], standardLibrary: true });
    assert.equal(initialize.params.processId, process.pid);
    assert.ok(vscode.commands.registered.has('gmac.restartServer'));
    // a changed setting restarts the server: the first one is shut down, a second one initialized
    fireConfigurationChange(['gmac.dslFolders']);
    await until(() => readLog(log).filter((m) => m.method === 'initialized').length === 2, 'the second initialized');
    const messages = readLog(log);
    const exitAt = messages.findIndex((m) => m.method === 'exit');
    const secondStart = messages.findIndex((m, i) => i > 0 && m.started);
    assert.ok(exitAt > 0 && exitAt < secondStart, 'the first server exits before the second starts');
    await extension.deactivate();
    await until(() => readLog(log).filter((m) => m.method === 'exit').length === 2, 'exit');
    assert.equal(readLog(log).filter((m) => m.method === 'shutdown').length, 2);
    assert.deepEqual(shown.warnings, []);
    assert.deepEqual(shown.errors, []);
    context.subscriptions.forEach((d) => d.dispose?.());
  } finally {
    uninstall();
    fs.rmSync(workspace, { recursive: true, force: true });
  }
});

test('a server command that does not exist is reported once, by the extension, and not retried', async () => {
  const workspace = fs.mkdtempSync(path.join(os.tmpdir(), 'gmac-ws-'));
  const { vscode, shown } = createStub({
    workspaceFolder: workspace,
    settings: { 'gmac.serverPath': path.join(workspace, 'no-such-gmac'), 'gmac.serverArgs': ['lsp'] },
  });
  const uninstall = installStub(vscode);
  try {
    const extension = freshExtension();
    const context = { subscriptions: [] };
    extension.activate(context);
    await until(() => shown.warnings.length > 0, 'the warning');
    await new Promise((r) => setTimeout(r, 500));
    assert.equal(shown.warnings.length, 1, shown.warnings.join('\n'));
    assert.match(shown.warnings[0], /could not start the language server \('.*no-such-gmac lsp'\)/);
    assert.deepEqual(shown.errors, [], 'and not by vscode-languageclient');
    assert.ok(shown.output.some((l) => /Could not start/.test(l)));
    await extension.deactivate();
    context.subscriptions.forEach((d) => d.dispose?.());
  } finally {
    uninstall();
    fs.rmSync(workspace, { recursive: true, force: true });
  }
});

test('with gmac.enableServer false no process is started', async () => {
  const { vscode, shown } = createStub({ settings: { 'gmac.enableServer': false, 'gmac.serverPath': '/nonexistent' } });
  const uninstall = installStub(vscode);
  try {
    const extension = freshExtension();
    extension.activate({ subscriptions: [] });
    await until(() => shown.output.length > 0, 'the output line');
    assert.match(shown.output.join('\n'), /gmac.enableServer is false/);
    assert.deepEqual(shown.warnings, []);
    await extension.deactivate();
  } finally {
    uninstall();
  }
});

test('a server that exits at once (dotnet gmac without the tool) is reported once and not restarted', async () => {
  const workspace = fs.mkdtempSync(path.join(os.tmpdir(), 'gmac-ws-'));
  const log = path.join(workspace, 'starts.log');
  const { vscode, shown } = createStub({
    workspaceFolder: workspace,
    settings: {
      'gmac.serverPath': process.execPath,
      'gmac.serverArgs': ['-e', `require('fs').appendFileSync(${JSON.stringify(log)}, 'start\\n'); console.error('Could not execute because the specified command or file was not found.'); process.exit(1)`],
    },
  });
  const uninstall = installStub(vscode);
  try {
    const extension = freshExtension();
    const context = { subscriptions: [] };
    extension.activate(context);
    await until(() => shown.errors.length + shown.warnings.length > 0, 'a notification');
    await new Promise((r) => setTimeout(r, 1000));
    // one notification, vscode-languageclient's (its 'Go to output' leads to the reason and what to do)
    assert.deepEqual(shown.warnings, []);
    assert.equal(shown.errors.length, 1, shown.errors.join('\n'));
    const text = shown.output.join('\n');
    assert.match(text, /Could not execute because the specified command or file was not found/, 'the server\'s standard error');
    assert.match(text, /gmac\.serverPath/);
    assert.equal(fs.readFileSync(log, 'utf8'), 'start\n', 'started once');
    await extension.deactivate();
    context.subscriptions.forEach((d) => d.dispose?.());
  } finally {
    uninstall();
    fs.rmSync(workspace, { recursive: true, force: true });
  }
});
