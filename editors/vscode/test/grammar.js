'use strict';
// Loads syntaxes/gmac.tmLanguage.json with vscode-textmate over the Oniguruma engine that VS Code uses,
// and tokenizes text into { line, text, scopes } records.
const fs = require('fs');
const path = require('path');
const oniguruma = require('vscode-oniguruma');
const textmate = require('vscode-textmate');

const root = path.join(__dirname, '..');
const grammarPath = path.join(root, 'syntaxes', 'gmac.tmLanguage.json');
const repositoryRoot = path.join(root, '..', '..');

let registryPromise;
function registry() {
  registryPromise ??= (async () => {
    const wasm = fs.readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm'));
    await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
    return new textmate.Registry({
      onigLib: Promise.resolve({
        createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
        createOnigString: (s) => new oniguruma.OnigString(s),
      }),
      loadGrammar: async (scopeName) => {
        if (scopeName !== 'source.gmac') return null;
        return textmate.parseRawGrammar(fs.readFileSync(grammarPath, 'utf8'), grammarPath);
      },
    });
  })();
  return registryPromise;
}

async function loadGrammar() {
  const grammar = await (await registry()).loadGrammar('source.gmac');
  if (!grammar) throw new Error(`cannot load ${grammarPath}`);
  return grammar;
}

/** Every token of text, line by line, the state carried across lines as an editor does. */
async function tokenize(text) {
  const grammar = await loadGrammar();
  const tokens = [];
  let state = textmate.INITIAL;
  text.split(/\r?\n/).forEach((line, index) => {
    const result = grammar.tokenizeLine(line, state);
    for (const t of result.tokens) {
      const end = Math.min(t.endIndex, line.length);
      if (end <= t.startIndex) continue;
      tokens.push({ line: index + 1, column: t.startIndex + 1, text: line.slice(t.startIndex, end), scopes: t.scopes });
    }
    state = result.ruleStack;
  });
  return tokens;
}

/** The keywords of the lexer part of GMacDsl.g4: every all-letter literal, such as 'define' or 'output' of OUTPUT_BLOCK. */
function lexerKeywords() {
  const g4 = fs.readFileSync(path.join(repositoryRoot, 'src', 'GMac.Dsl', 'Syntax', 'GMacDsl.g4'), 'utf8');
  const lexer = g4.slice(g4.search(/^\/\/ -+ lexer/m));
  if (lexer.length === g4.length) throw new Error('no lexer section in GMacDsl.g4');
  const words = new Set();
  for (const line of lexer.split('\n')) {
    if (line.trim().startsWith('//')) continue;
    for (const m of line.matchAll(/'([A-Za-z_]+)'/g)) words.add(m[1]);
  }
  return [...words];
}

module.exports = { tokenize, loadGrammar, lexerKeywords, grammarPath, repositoryRoot };
