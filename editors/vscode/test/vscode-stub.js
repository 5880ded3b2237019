'use strict';
// Just enough of the vscode module for src/extension.js and vscode-languageclient to run under node:
// the parts the client reads are real (settings, workspace folder, output channel, messages, events);
// every other member is an inert stand-in that accepts any use.
const Module = require('module');
const path = require('path');

function inert() {
  const target = function () {};
  return new Proxy(target, {
    get(_t, key) {
      if (key === 'then') return undefined; // not a promise
      if (key === Symbol.iterator) return function* () {};
      if (key === Symbol.toPrimitive) return () => '';
      if (key === 'dispose') return () => undefined;
      return inert();
    },
    apply: () => inert(),
    construct: () => inert(),
  });
}

class Disposable {
  constructor(fn) { this.fn = fn; }
  static from(...items) { return new Disposable(() => items.forEach((d) => d?.dispose?.())); }
  dispose() { this.fn?.(); }
}

class EventEmitter {
  constructor() {
    this.listeners = [];
    this.event = (listener) => {
      this.listeners.push(listener);
      return new Disposable(() => { this.listeners = this.listeners.filter((l) => l !== listener); });
    };
  }
  fire(value) { for (const l of [...this.listeners]) l(value); }
  dispose() { this.listeners = []; }
}

/** A fresh stand-in for vscode, with settings and one workspace folder; records what it shows. */
function createStub({ settings = {}, workspaceFolder }) {
  const shown = { warnings: [], errors: [], infos: [], output: [] };
  const uri = (fsPath) => ({ scheme: 'file', fsPath, path: fsPath, toString: () => `file://${fsPath}`, with: () => uri(fsPath) });
  const configuration = (section) => ({
    get: (key, fallback) => {
      const full = section ? `${section}.${key}` : key;
      return Object.prototype.hasOwnProperty.call(settings, full) ? settings[full] : fallback;
    },
    has: () => false,
    inspect: () => undefined,
    update: async () => undefined,
  });
  const onConfiguration = new EventEmitter();
  const base = {
    __esModule: true,
    version: '1.106.0',
    Disposable,
    EventEmitter,
    Uri: { file: uri, parse: (s) => uri(s.replace(/^file:\/\//, '')) },
    ConfigurationTarget: { Global: 1, Workspace: 2, WorkspaceFolder: 3 },
    LogLevel: { Off: 0, Trace: 1, Debug: 2, Info: 3, Warning: 4, Error: 5 },
    workspace: {
      workspaceFolders: workspaceFolder ? [{ uri: uri(workspaceFolder), name: path.basename(workspaceFolder), index: 0 }] : undefined,
      textDocuments: [],
      notebookDocuments: [],
      getConfiguration: configuration,
      onDidChangeConfiguration: onConfiguration.event,
      createFileSystemWatcher: () => new Proxy({ dispose() {} }, { get: (t, k) => (k in t ? t[k] : inert()) }),
    },
    window: {
      // As in VS Code: info(), warn(), ... only on a channel created with { log: true }.
      createOutputChannel: (name, options) => {
        const channel = {
          name,
          append: (s) => shown.output.push(s),
          appendLine: (s) => shown.output.push(s),
          replace: () => undefined, clear: () => undefined, show: () => undefined, hide: () => undefined, dispose: () => undefined,
        };
        if (!options?.log) return channel;
        const log = (level) => (message) => shown.output.push(`[${level}] ${message}`);
        return {
          ...channel,
          logLevel: 3,
          onDidChangeLogLevel: () => new Disposable(),
          trace: log('trace'), debug: log('debug'), info: log('info'), warn: log('warn'), error: log('error'),
        };
      },
      showWarningMessage: async (m) => { shown.warnings.push(m); return undefined; },
      showErrorMessage: async (m) => { shown.errors.push(m); return undefined; },
      showInformationMessage: async (m) => { shown.infos.push(m); return undefined; },
      visibleTextEditors: [],
      tabGroups: { all: [], onDidChangeTabs: () => new Disposable() },
    },
    commands: {
      registered: new Map(),
      registerCommand(name, fn) { this.registered.set(name, fn); return new Disposable(() => this.registered.delete(name)); },
      executeCommand: async () => undefined,
    },
  };
  const vscode = deepInert(base);
  return { vscode, shown, fireConfigurationChange: (sections) => onConfiguration.fire({ affectsConfiguration: (s) => sections.includes(s) }) };
}

// Members the stub defines are real; any other (languages.registerHoverProvider, CodeActionKind, ...)
// is inert, at any depth of a defined namespace.
function deepInert(object) {
  return new Proxy(object, {
    get(target, key) {
      if (key in target) {
        const value = target[key];
        return value && Object.getPrototypeOf(value) === Object.prototype ? deepInert(value) : value;
      }
      if (key === 'then') return undefined;
      return inert();
    },
  });
}

/** Makes require('vscode') return stub until the returned function is called. */
function installStub(stub) {
  const original = Module._load;
  Module._load = function (request, ...rest) {
    if (request === 'vscode') return stub;
    return original.call(this, request, ...rest);
  };
  return () => { Module._load = original; };
}

module.exports = { createStub, installStub };
