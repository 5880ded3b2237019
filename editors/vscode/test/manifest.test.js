'use strict';
// What package.json declares: files that exist, the gmac problem matcher against the lines gmac and
// MSBuild print, the language configuration, the snippets, and how the client picks its command.
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { serverCommand, initializationOptions, findOnPath, expand } = require('../src/server-command');

const root = path.join(__dirname, '..');
const manifest = JSON.parse(fs.readFileSync(path.join(root, 'package.json'), 'utf8'));
const contributes = manifest.contributes;

test('package.json: the gmac language, its grammar, configuration and snippets exist', () => {
  const language = contributes.languages.find((l) => l.id === 'gmac');
  assert.deepEqual(language.extensions, ['.gmac']);
  for (const file of [language.configuration, contributes.grammars[0].path, contributes.snippets[0].path, manifest.main]) {
    assert.ok(fs.existsSync(path.join(root, file)), file);
  }
  assert.equal(contributes.grammars[0].scopeName, 'source.gmac');
  const grammar = JSON.parse(fs.readFileSync(path.join(root, contributes.grammars[0].path), 'utf8'));
  assert.equal(grammar.scopeName, 'source.gmac');
});

test('package.json: every setting the client reads is declared, every command registered', () => {
  const declared = Object.keys(contributes.configuration.properties);
  const source = fs.readFileSync(path.join(root, 'src', 'extension.js'), 'utf8');
  for (const key of source.matchAll(/config\.get\('([^']+)'/g)) assert.ok(declared.includes(`gmac.${key[1]}`), key[1]);
  for (const command of contributes.commands) assert.ok(source.includes(`'${command.command}'`), command.command);
  assert.ok(declared.includes('gmac.trace.server'), 'the trace setting vscode-languageclient reads for the client id gmac');
  assert.ok(source.includes("new LanguageClient('gmac'"));
});

function problem(line) {
  const pattern = contributes.problemPatterns.find((p) => p.name === 'gmac');
  const m = new RegExp(pattern.regexp).exec(line);
  if (!m) return null;
  return { file: m[pattern.file], line: +m[pattern.line], column: +m[pattern.column], severity: m[pattern.severity], code: m[pattern.code], message: m[pattern.message] };
}

test('problem matcher $gmac: the lines of gmac check and of an MSBuild build', () => {
  const matcher = contributes.problemMatchers.find((m) => m.name === 'gmac');
  assert.equal(matcher.pattern, '$gmac');
  assert.deepEqual(problem("dsl/macros/twister.gmac(12,9): error GMAC0301: unknown name 'foo'"), {
    file: 'dsl/macros/twister.gmac', line: 12, column: 9, severity: 'error', code: 'GMAC0301', message: "unknown name 'foo'" });
  assert.deepEqual(problem('/home/u/p/Program.cs(40,5): warning GMAC0411: README.md is not a C# file [/home/u/p/p.csproj]'), {
    file: '/home/u/p/Program.cs', line: 40, column: 5, severity: 'warning', code: 'GMAC0411', message: 'README.md is not a C# file' });
  assert.deepEqual(problem('    C:\\src\\My Project\\K.cs(3,1): error GMAC0406: the file changed (a) [C:\\src\\p.csproj::TargetFramework=net10.0]'), {
    file: 'C:\\src\\My Project\\K.cs', line: 3, column: 1, severity: 'error', code: 'GMAC0406', message: 'the file changed (a)' });
  // as printed by gmac check on an earlier version of test/fixtures/all-syntax.gmac
  assert.deepEqual(problem("editors/vscode/test/fixtures/all-syntax.gmac(67,14): error GMAC0110: operands belong to different frames 'a' and 'e3d'"), {
    file: 'editors/vscode/test/fixtures/all-syntax.gmac', line: 67, column: 14, severity: 'error', code: 'GMAC0110', message: "operands belong to different frames 'a' and 'e3d'" });
  assert.equal(problem('Program.cs(1,1): error CS1002: ; expected'), null, 'C# errors are $msCompile\'s');
  assert.equal(problem('tests: 3 passed, 0 failed, 0 skipped'), null);
});

test('language configuration: comments, brackets, folding on define ... end', () => {
  const config = JSON.parse(fs.readFileSync(path.join(root, 'language-configuration.json'), 'utf8'));
  assert.equal(config.comments.lineComment, '//');
  assert.deepEqual(config.comments.blockComment, ['/*', '*/']);
  const start = new RegExp(config.folding.markers.start);
  const end = new RegExp(config.folding.markers.end);
  assert.ok(start.test('define macro M as'));
  assert.ok(start.test('  define normalized multivector class e3d.Unit as'));
  assert.ok(!start.test('define subspace e3d.scalars as basis {1} end subspace'), 'a one-line definition does not fold');
  for (const kind of ['frame', 'transform', 'subspace', 'multivector class', 'constant', 'binding', 'macro']) {
    assert.ok(end.test(`end ${kind}`), kind);
  }
  assert.ok(!end.test('endpoint = 1;'));
});

test('snippets: each has a prefix and a body, and every definition snippet ends what it defines', () => {
  const snippets = JSON.parse(fs.readFileSync(path.join(root, 'snippets', 'gmac.json'), 'utf8'));
  assert.ok(Object.keys(snippets).length >= 10);
  for (const [name, s] of Object.entries(snippets)) {
    assert.ok(s.prefix && Array.isArray(s.body) && s.body.length > 0, name);
    const body = s.body.join('\n');
    const kind = /^define (?:normalized )?(multivector class|\w+)/.exec(body)?.[1];
    if (kind) assert.match(body, new RegExp(`end ${kind}\\b`), name);
  }
});

test('server command: gmac.serverPath and gmac.serverArgs win, with ${workspaceFolder} and ~ expanded', () => {
  const c = serverCommand({ serverPath: '${workspaceFolder}/bin/gmac', serverArgs: ['lsp', '--log', '~/gmac.log'], workspaceFolder: '/w' }, () => '/usr/bin/gmac');
  assert.deepEqual(c, { command: '/w/bin/gmac', args: ['lsp', '--log', path.join(os.homedir(), 'gmac.log')], source: 'gmac.serverPath' });
});

test('server command: gmac on the PATH, else dotnet gmac lsp', () => {
  assert.deepEqual(serverCommand({ serverPath: '', serverArgs: ['lsp'] }, () => '/opt/bin/gmac'), { command: '/opt/bin/gmac', args: ['lsp'], source: 'PATH' });
  assert.deepEqual(serverCommand({ serverPath: '  ', serverArgs: ['lsp'] }, () => undefined), { command: 'dotnet', args: ['gmac', 'lsp'], source: 'dotnet tool' });
  assert.deepEqual(serverCommand({}, () => undefined), { command: 'dotnet', args: ['gmac', 'lsp'], source: 'dotnet tool' });
});

test('findOnPath finds an executable file, skips a non-executable one and folders', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'gmac-path-'));
  try {
    const plain = path.join(dir, 'plain');
    const bin = path.join(dir, 'bin');
    fs.mkdirSync(plain);
    fs.mkdirSync(bin);
    fs.mkdirSync(path.join(plain, 'gmac')); // a folder named gmac is not the tool
    fs.writeFileSync(path.join(bin, 'gmac'), '#!/bin/sh\n', { mode: 0o644 });
    const env = { PATH: [plain, bin].join(':') };
    assert.equal(findOnPath('gmac', env, 'linux'), undefined, 'not executable');
    fs.chmodSync(path.join(bin, 'gmac'), 0o755);
    assert.equal(findOnPath('gmac', env, 'linux'), path.join(bin, 'gmac'));
    assert.equal(findOnPath('gmac', { PATH: '' }, 'linux'), undefined);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

test('initializationOptions: DSL folders made absolute against the workspace folder', () => {
  assert.deepEqual(initializationOptions({ dslFolders: ['dsl', '/abs/lib', '${workspaceFolder}/more'], standardLibrary: true, workspaceFolder: '/w' }),
    { dslFolders: [path.resolve('/w', 'dsl'), '/abs/lib', '/w/more'], standardLibrary: true });
  assert.deepEqual(initializationOptions({}), { dslFolders: [], standardLibrary: false });
  assert.equal(expand('~', '/w'), os.homedir());
});
