'use strict';
// Which process the client starts and what it tells the server at initialize. No dependency on the
// vscode module, so the tests run it under plain node.

const fs = require('fs');
const os = require('os');
const path = require('path');

/** The full path of an executable named name on the PATH, or undefined. */
function findOnPath(name, env = process.env, platform = process.platform) {
  const delimiter = platform === 'win32' ? ';' : ':';
  const dirs = (env.PATH ?? env.Path ?? '').split(delimiter).filter(Boolean);
  const extensions = platform === 'win32' ? ['', ...(env.PATHEXT ?? '.COM;.EXE;.BAT;.CMD').split(';').filter(Boolean)] : [''];
  for (const dir of dirs) {
    for (const extension of extensions) {
      const candidate = path.join(dir, name + extension);
      try {
        if (!fs.statSync(candidate).isFile()) continue;
        if (platform !== 'win32') fs.accessSync(candidate, fs.constants.X_OK);
        return candidate;
      } catch {
        // not there, or not executable
      }
    }
  }
  return undefined;
}

/** Whether command names an executable: a path to one, or a name found on the PATH. */
function commandExists(command, env = process.env, platform = process.platform) {
  if (path.isAbsolute(command) || command.includes('/') || (platform === 'win32' && command.includes('\\'))) {
    try {
      if (!fs.statSync(command).isFile()) return false;
      if (platform !== 'win32') fs.accessSync(command, fs.constants.X_OK);
      return true;
    } catch {
      return false;
    }
  }
  return findOnPath(command, env, platform) !== undefined;
}

/** ${workspaceFolder} and a leading ~ in a setting. */
function expand(value, workspaceFolder) {
  let result = String(value);
  if (workspaceFolder) result = result.split('${workspaceFolder}').join(workspaceFolder);
  if (result === '~' || result.startsWith('~/') || result.startsWith('~\\')) result = os.homedir() + result.slice(1);
  return result;
}

/**
 * The command and arguments of the server: gmac.serverPath with gmac.serverArgs; else gmac on the
 * PATH; else `dotnet gmac` (a dotnet tool, local to the workspace's tool manifest or global).
 */
function serverCommand(settings, lookup = findOnPath) {
  const workspaceFolder = settings.workspaceFolder;
  const args = (Array.isArray(settings.serverArgs) ? settings.serverArgs : ['lsp']).map((a) => expand(a, workspaceFolder));
  const configured = String(settings.serverPath ?? '').trim();
  if (configured) return { command: expand(configured, workspaceFolder), args, source: 'gmac.serverPath' };
  const onPath = lookup('gmac');
  if (onPath) return { command: onPath, args, source: 'PATH' };
  return { command: 'dotnet', args: ['gmac', ...args], source: 'dotnet tool' };
}

/** What the client sends as initializationOptions: absolute DSL folders and the standard-library switch. */
function initializationOptions(settings) {
  const base = settings.workspaceFolder;
  const folders = Array.isArray(settings.dslFolders) ? settings.dslFolders : [];
  return {
    dslFolders: folders.map((f) => {
      const expanded = expand(f, base);
      return base && !path.isAbsolute(expanded) ? path.resolve(base, expanded) : expanded;
    }),
    standardLibrary: Boolean(settings.standardLibrary),
  };
}

module.exports = { findOnPath, commandExists, expand, serverCommand, initializationOptions };
