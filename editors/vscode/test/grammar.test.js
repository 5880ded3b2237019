'use strict';
// The TextMate grammar, tokenized with vscode-textmate and Oniguruma as VS Code does: the dsl/
// library, every keyword of the lexer in GMacDsl.g4, and lines where the lexer's rules are subtle.
const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('fs');
const path = require('path');
const { tokenize, lexerKeywords, grammarPath, repositoryRoot } = require('./grammar');

const dslFolder = path.join(repositoryRoot, 'dsl');
const fixture = path.join(__dirname, 'fixtures', 'all-syntax.gmac');

function gmacFiles(folder) {
  return fs.readdirSync(folder, { withFileTypes: true }).flatMap((entry) => {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) return gmacFiles(full);
    return entry.name.endsWith('.gmac') ? [full] : [];
  }).sort();
}

const innermost = (token) => token.scopes[token.scopes.length - 1];
const isKeyword = (token) => /^keyword\./.test(innermost(token));
const inComment = (token) => token.scopes.some((s) => s.startsWith('comment.'));

/** The tokens of one line of text, without blanks; each as [text, innermost scope]. */
async function lineTokens(text) {
  return (await tokenize(text)).filter((t) => t.text.trim() !== '').map((t) => [t.text, innermost(t)]);
}

/** The innermost scope of the first token whose text is exactly text (the nth such token). */
function scopeOf(tokens, text, nth = 0) {
  const found = tokens.filter(([t]) => t === text);
  assert.ok(found.length > nth, `no token '${text}' (#${nth}) in ${JSON.stringify(tokens)}`);
  return found[nth][1];
}

const library = gmacFiles(dslFolder);

test('the dsl/ library has .gmac files to tokenize', () => {
  assert.ok(library.length >= 10, `only ${library.length} .gmac files under ${dslFolder}`);
});

for (const file of [...library, fixture]) {
  const name = path.relative(repositoryRoot, file);
  test(`${name}: every token has a scope of its own, none invalid`, async () => {
    const tokens = await tokenize(fs.readFileSync(file, 'utf8'));
    const problems = tokens.filter((t) => t.text.trim() !== '').filter((t) => {
      const last = innermost(t);
      return last === 'source.gmac' || last.startsWith('meta.') || t.scopes.some((s) => s.startsWith('invalid.'));
    });
    assert.deepEqual(problems.map((t) => `${t.line}:${t.column} ${JSON.stringify(t.text)} ${t.scopes.join(' ')}`), []);
  });

  test(`${name}: every keyword of the lexer outside comments has a keyword scope`, async () => {
    const keywords = new Set(lexerKeywords());
    const tokens = await tokenize(fs.readFileSync(file, 'utf8'));
    const wrong = tokens.filter((t) => !inComment(t) && keywords.has(t.text) && !isKeyword(t)
      // a keyword is an ordinary name where the grammar allows it: inverse(u), a member <min>,
      // the text of an output block, a blade or a placeholder
      && !/^(support\.function|variable\.other\.member|string\.unquoted\.output|constant\.other\.blade)/.test(innermost(t)));
    assert.deepEqual(wrong.map((t) => `${t.line}:${t.column} ${t.text} ${t.scopes.join(' ')}`), []);
  });
}

test('every keyword of the lexer gets a keyword scope somewhere in dsl/ or the all-syntax fixture', async () => {
  const seen = new Set();
  for (const file of [...library, fixture]) {
    for (const t of await tokenize(fs.readFileSync(file, 'utf8'))) if (isKeyword(t)) seen.add(t.text);
  }
  const missing = lexerKeywords().filter((k) => !seen.has(k));
  assert.deepEqual(missing, []);
});

test('every keyword of the lexer is in the TextMate grammar, and the grammar has no keyword the lexer lacks', () => {
  const keywords = lexerKeywords();
  assert.ok(keywords.length >= 45, `only ${keywords.length} keywords read from GMacDsl.g4: ${keywords}`);
  const grammar = JSON.parse(fs.readFileSync(grammarPath, 'utf8'));
  // The alternatives of every keyword rule, and of every begin pattern (the definition headers, output).
  const words = new Set();
  const collect = (node) => {
    if (Array.isArray(node)) return node.forEach(collect);
    if (!node || typeof node !== 'object') return;
    const isKeywordRule = typeof node.name === 'string' && node.name.startsWith('keyword.');
    for (const key of ['match', 'begin', 'end']) {
      if (typeof node[key] !== 'string') continue;
      const keywordGroups = key === 'match' && isKeywordRule ? [node[key]]
        : Object.entries(node[`${key}Captures`] ?? node.captures ?? {})
          .filter(([, c]) => c.name?.startsWith('keyword.')).map(() => node[key]);
      for (const source of keywordGroups) for (const w of source.match(/[A-Za-z_]{2,}/g) ?? []) words.add(w);
    }
    Object.values(node).forEach(collect);
  };
  collect(grammar.repository);
  const missing = keywords.filter((k) => !words.has(k));
  assert.deepEqual(missing, [], 'lexer keywords missing from the grammar');
  // Words of keyword rules that are not lexer keywords (character classes like A-Za-z aside).
  const keywordRules = [];
  const rules = (node) => {
    if (Array.isArray(node)) return node.forEach(rules);
    if (!node || typeof node !== 'object') return;
    if (typeof node.match === 'string' && typeof node.name === 'string' && node.name.startsWith('keyword.')) keywordRules.push(node.match);
    Object.values(node).forEach(rules);
  };
  rules(grammar.repository);
  const extra = keywordRules.flatMap((r) => r.replace(/\[[^\]]*\]/g, '').match(/[A-Za-z_]{2,}/g) ?? [])
    .filter((w) => !keywords.includes(w));
  assert.deepEqual([...new Set(extra)], [], 'keyword rules with words the lexer does not have');
});

test('each lexer keyword alone on a line is a keyword', async () => {
  for (const keyword of lexerKeywords()) {
    const tokens = await lineTokens(keyword === 'output' ? 'output { }' : `${keyword} x`);
    assert.match(scopeOf(tokens, keyword), /^keyword\./, keyword);
  }
});

test('keywords are case-sensitive, as in the lexer', async () => {
  const tokens = await lineTokens('Define FRAME euclidean ipm bcm Euclidean IPM BCM');
  assert.deepEqual(tokens.map(([, s]) => s), [
    'variable.other.gmac', 'variable.other.gmac', 'variable.other.gmac', 'variable.other.gmac', 'variable.other.gmac',
    'keyword.other.gmac', 'keyword.other.gmac', 'keyword.other.gmac',
  ]);
});

test('block comments do not nest: the first */ ends one, as in the lexer', async () => {
  const tokens = await tokenize('x = a /* one /* two */ b */ + 1;');
  const b = tokens.find((t) => t.text === 'b');
  assert.ok(!inComment(b), 'b follows the first */ and is code');
  assert.equal(innermost(b), 'variable.other.gmac');
  const afterB = tokens.filter((t) => t.column > b.column && t.text.trim() !== '');
  assert.deepEqual(afterB.map((t) => [t.text, innermost(t)]), [
    ['*', 'keyword.operator.arithmetic.gmac'],
    ['/', 'keyword.operator.arithmetic.gmac'],
    ['+', 'keyword.operator.arithmetic.gmac'],
    ['1', 'constant.numeric.integer.gmac'],
    [';', 'punctuation.terminator.statement.gmac'],
  ]);
  const inner = tokens.find((t) => t.text.includes('two'));
  assert.ok(inComment(inner));
});

test('a block comment spans lines and sits inside an expression', async () => {
  const tokens = await tokenize('y = a /* first line\n  // not a line comment, still the block\n */ gp b;');
  const gp = tokens.find((t) => t.text === 'gp');
  assert.equal(innermost(gp), 'keyword.operator.word.gmac');
  const middle = tokens.filter((t) => t.line === 2);
  assert.ok(middle.every((t) => t.scopes.includes('comment.block.gmac')), JSON.stringify(middle));
  assert.ok(!middle.some((t) => t.scopes.includes('comment.line.double-slash.gmac')));
});

test('a line comment ends at the end of its line and hides /* from the lexer', async () => {
  const tokens = await tokenize('a = b; // c /* not opened\nd = e;');
  const d = tokens.find((t) => t.text === 'd');
  assert.equal(innermost(d), 'variable.other.gmac');
  assert.ok(tokens.filter((t) => t.line === 1 && t.column >= 8).every(inComment));
});

test('a lone /* with no */ is an unterminated comment to the end of the text', async () => {
  const tokens = await tokenize('a = 1 /* open\nb = 2;');
  assert.ok(tokens.filter((t) => t.line === 2).every(inComment));
});

test('numbers: integers, decimals, exponents with and without a sign', async () => {
  const tokens = await lineTokens('x = 1.5e-3 + 2E+4 + 3.25 + 7 + 1e9 + 6.02e23 + 0.5;');
  for (const n of ['1.5e-3', '2E+4', '3.25', '1e9', '6.02e23', '0.5']) assert.equal(scopeOf(tokens, n), 'constant.numeric.float.gmac', n);
  assert.equal(scopeOf(tokens, '7'), 'constant.numeric.integer.gmac');
});

test('numbers split where the lexer splits them: 1.e3 is 1 . e3, 1e is 1 e, e1 is a name', async () => {
  assert.deepEqual(await lineTokens('1.e3'), [
    ['1', 'constant.numeric.integer.gmac'], ['.', 'punctuation.accessor.gmac'], ['e3', 'variable.other.gmac']]);
  assert.deepEqual(await lineTokens('1e + e1'), [
    ['1', 'constant.numeric.integer.gmac'], ['e', 'variable.other.gmac'], ['+', 'keyword.operator.arithmetic.gmac'],
    ['e1', 'variable.other.gmac']]);
});

test('operators: the product words, arithmetic, power, assignment, the transform arrow', async () => {
  const tokens = await lineTokens('r = a gp b op c sp d lcp e rcp f fdp g hip h cp i acp j + k - l * m / n ^ 2;');
  for (const w of ['gp', 'op', 'sp', 'lcp', 'rcp', 'fdp', 'hip', 'cp', 'acp']) assert.equal(scopeOf(tokens, w), 'keyword.operator.word.gmac', w);
  for (const o of ['+', '-', '*', '/']) assert.equal(scopeOf(tokens, o), 'keyword.operator.arithmetic.gmac', o);
  assert.equal(scopeOf(tokens, '^'), 'keyword.operator.power.gmac');
  assert.equal(scopeOf(tokens, '='), 'keyword.operator.assignment.gmac');
  const arrow = await lineTokens('define transform t : a -> b as identity end transform');
  assert.equal(scopeOf(arrow, '->'), 'keyword.operator.arrow.gmac');
  // product words are whole words: gpx, ops are names
  const names = await lineTokens('gpx ops cp2');
  assert.deepEqual(names.map(([, s]) => s), ['variable.other.gmac', 'variable.other.gmac', 'variable.other.gmac']);
});

test('<u.e1^e2>, <x>, <ray.origin.x> are member references; x.<e1^e2> and x.<1> coefficients', async () => {
  const tokens = await tokenize('y = <u.e1^e2> + <x>^2 + <ray.origin.x> + x.<e1^e2> * x.<1>;');
  const at = (text, nth = 0) => tokens.filter((t) => t.text === text)[nth];
  assert.ok(at('<').scopes.includes('meta.member-reference.gmac'));
  assert.equal(innermost(at('u')), 'variable.other.member.gmac');
  assert.equal(innermost(at('e1')), 'constant.other.blade.gmac', 'e1^e2 after the dot is a blade');
  assert.equal(innermost(tokens.find((t) => t.text === '^' && t.scopes.includes('meta.member-reference.gmac'))), 'punctuation.separator.wedge.gmac');
  assert.equal(innermost(at('x')), 'variable.other.member.gmac');
  assert.equal(innermost(at('^', 1)), 'keyword.operator.power.gmac');
  assert.equal(innermost(at('origin')), 'variable.other.member.gmac');
  const coefficients = tokens.filter((t) => t.scopes.includes('meta.coefficient.gmac'));
  assert.deepEqual(coefficients.map((t) => [t.text, innermost(t)]), [
    ['.', 'punctuation.accessor.gmac'], ['<', 'punctuation.definition.coefficient.begin.gmac'],
    ['e1', 'constant.other.blade.gmac'], ['^', 'punctuation.separator.wedge.gmac'],
    ['e2', 'constant.other.blade.gmac'], ['>', 'punctuation.definition.coefficient.end.gmac'],
    ['.', 'punctuation.accessor.gmac'], ['<', 'punctuation.definition.coefficient.begin.gmac'],
    ['1', 'constant.numeric.integer.gmac'], ['>', 'punctuation.definition.coefficient.end.gmac'],
  ]);
});

test('blade names: e1^e2^e3 in coefficient lists and subspaces; ^ before a number is the power', async () => {
  const tokens = await tokenize('define constant e3d.I as multivector { e1^e2^e3 : 1; no ^ ni : x^2 } end constant');
  const blade = tokens.filter((t) => t.scopes.includes('constant.other.blade.gmac')).map((t) => t.text).join('');
  assert.equal(blade, 'e1^e2^e3no ^ ni');
  const power = tokens.filter((t) => t.text === '^' && innermost(t) === 'keyword.operator.power.gmac');
  assert.equal(power.length, 1);
  const header = tokens.filter((t) => t.line === 1 && t.column < 22 && t.text.trim());
  assert.deepEqual(header.map((t) => [t.text, innermost(t)]), [
    ['define', 'keyword.other.define.gmac'], ['constant', 'keyword.other.gmac'],
    ['e3d', 'variable.other.constant.gmac'], ['.', 'punctuation.accessor.gmac'], ['I', 'variable.other.constant.gmac']]);
});

test('define macro X as ... end macro is one definition block with its name, parameters and types', async () => {
  const text = [
    'define macro X as',
    '    inputs: { a : e3d.Vector; b as e3d.Bivector }',
    '    outputs: { c : e3d.Vector }',
    '    performs:',
    '        c = a lcp b;',
    'end macro',
    'x',
  ].join('\n');
  const tokens = await tokenize(text);
  const meta = 'meta.definition.macro.gmac';
  assert.ok(tokens.filter((t) => t.line <= 6).every((t) => t.scopes.includes(meta)));
  assert.ok(!tokens.find((t) => t.line === 7).scopes.includes(meta), 'the block ends at end macro');
  const at = (text, nth = 0) => innermost(tokens.filter((t) => t.text === text)[nth]);
  assert.equal(at('X'), 'entity.name.function.macro.gmac');
  assert.equal(at('a'), 'variable.parameter.gmac');
  assert.equal(at('b'), 'variable.parameter.gmac');
  assert.equal(at('as', 1), 'keyword.other.gmac');
  assert.equal(at('Vector'), 'entity.name.type.class.gmac');
  assert.equal(at('Bivector'), 'entity.name.type.class.gmac');
  assert.equal(at('a', 1), 'variable.other.gmac');
  assert.equal(at('end'), 'keyword.other.end.gmac');
  assert.equal(at('macro', 1), 'keyword.other.gmac');
});

test('each kind of definition has its block and its name scope, on one line or several', async () => {
  const cases = [
    ['define frame e3d as basis: {e1, e2, e3} Euclidean end frame', 'frame', 'e3d', 'entity.name.type.frame.gmac'],
    ['define transform t : a -> b as identity end transform', 'transform', 't', 'entity.name.function.transform.gmac'],
    ['define subspace e3d.vectors as basis {e1, e2, e3} end subspace', 'subspace', 'vectors', 'entity.name.type.subspace.gmac'],
    ['define normalized multivector class e3d.Unit as\n  vectors\nend multivector class', 'class', 'Unit', 'entity.name.type.class.gmac'],
    ['define constant e3d.I as multivector { e1^e2^e3 : 1 } end constant', 'constant', 'I', 'variable.other.constant.gmac'],
    ['define binding P as\n  use frame e3d\n  bind { e1 : <x> }\nend binding', 'binding', 'P', 'entity.name.type.binding.gmac'],
  ];
  for (const [text, kind, name, scope] of cases) {
    const tokens = await tokenize(`${text}\nafter`);
    assert.equal(innermost(tokens.find((t) => t.text === name)), scope, text);
    const meta = `meta.definition.${kind}.gmac`;
    assert.ok(tokens.filter((t) => t.text !== 'after').every((t) => t.scopes.includes(meta)), text);
    assert.ok(!tokens.find((t) => t.text === 'after').scopes.includes(meta), `${text}: the block ends`);
  }
});

test('output { ... } is raw text up to the matching brace, with nested braces and placeholders', async () => {
  const tokens = await tokenize('output { // generated comment with <w.e1^e2> and { braces } };\nx = 1;');
  const body = tokens.filter((t) => t.line === 1);
  assert.equal(innermost(body[0]), 'keyword.other.output.gmac');
  // // inside the block is text, not a comment: the lexer reads the block as one token
  assert.ok(!body.some(inComment));
  assert.ok(body.find((t) => t.text.includes('generated comment')).scopes.includes('string.unquoted.output.gmac'));
  assert.equal(innermost(body.find((t) => t.text === 'w')), 'variable.other.gmac');
  assert.ok(body.find((t) => t.text === 'w').scopes.includes('meta.placeholder.gmac'));
  const closing = body.filter((t) => t.text === '}');
  assert.deepEqual(closing.map(innermost), ['punctuation.section.block.end.output.gmac', 'punctuation.section.block.end.output.gmac']);
  assert.equal(innermost(body.find((t) => t.text === ';')), 'punctuation.terminator.statement.gmac');
  assert.ok(!tokens.find((t) => t.line === 2 && t.text === 'x').scopes.includes('meta.output-block.gmac'));
});

test('output with its brace on the next line, and output as an ordinary name', async () => {
  const tokens = await tokenize('output\n  {\n    double y = 2 * <u.e1>;\n  }\noutputs: { }\noutputx = 1;');
  assert.ok(tokens.find((t) => t.text.includes('double')).scopes.includes('string.unquoted.output.gmac'));
  assert.ok(tokens.find((t) => t.line === 3 && t.text === 'u').scopes.includes('meta.placeholder.gmac'));
  assert.equal(innermost(tokens.find((t) => t.text === 'outputs')), 'keyword.other.gmac');
  assert.equal(innermost(tokens.find((t) => t.text === 'outputx')), 'variable.other.gmac');
});

test('there are no strings: a quote is a character the lexer rejects, inside an output block it is text', async () => {
  const tokens = await lineTokens('x = "text";');
  assert.equal(scopeOf(tokens, '"'), 'invalid.illegal.character.gmac');
  assert.equal(scopeOf(tokens, 'text'), 'variable.other.gmac');
  const block = await tokenize('output { s = "a"; }');
  assert.ok(!block.some((t) => t.scopes.some((s) => s.startsWith('invalid.'))));
  // and a } inside such a "string" ends the block, as it ends the lexer's OUTPUT_BLOCK
  const early = await tokenize('output { s = "}"; }');
  const quote = early.filter((t) => t.text.includes('"'));
  assert.equal(innermost(quote[quote.length - 1]), 'invalid.illegal.character.gmac');
});

test('other characters the lexer rejects are invalid: # @ ! and non-ASCII letters', async () => {
  const tokens = await lineTokens('# @ ! é');
  assert.deepEqual(tokens.map(([, s]) => s), Array(4).fill('invalid.illegal.character.gmac'));
  // in comments they are fine
  const comment = await tokenize('// no·ni = −1, I⁻¹ "quoted"');
  assert.ok(!comment.some((t) => t.scopes.some((s) => s.startsWith('invalid.'))));
});

test('built-in functions and macro calls; keywords usable as names stay keywords except as built-ins', async () => {
  const tokens = await lineTokens('y = sin(t) + reverse(m) + inverse(u) + Twice(u) + id[u] + pi; inverse of t; signature (3, 0, 1)');
  assert.equal(scopeOf(tokens, 'sin'), 'support.function.scalar.gmac');
  assert.equal(scopeOf(tokens, 'reverse'), 'support.function.builtin.gmac');
  assert.equal(scopeOf(tokens, 'inverse'), 'support.function.builtin.gmac');
  assert.equal(scopeOf(tokens, 'inverse', 1), 'keyword.other.gmac');
  assert.equal(scopeOf(tokens, 'Twice'), 'entity.name.function.call.gmac');
  assert.equal(scopeOf(tokens, 'id'), 'entity.name.function.transform.gmac');
  assert.equal(scopeOf(tokens, 'pi'), 'support.constant.pi.gmac');
  assert.equal(scopeOf(tokens, 'signature'), 'keyword.other.gmac');
});

test('statements: call, join on/off, punctuation', async () => {
  const tokens = await lineTokens('join on call Inner { a : u; b : z }; join off');
  assert.deepEqual(tokens, [
    ['join', 'keyword.control.gmac'], ['on', 'keyword.control.gmac'], ['call', 'keyword.control.gmac'],
    ['Inner', 'variable.other.gmac'], ['{', 'punctuation.section.braces.begin.gmac'], ['a', 'variable.other.gmac'],
    [':', 'punctuation.separator.colon.gmac'], ['u', 'variable.other.gmac'], [';', 'punctuation.terminator.statement.gmac'],
    ['b', 'variable.other.gmac'], [':', 'punctuation.separator.colon.gmac'], ['z', 'variable.other.gmac'],
    ['}', 'punctuation.section.braces.end.gmac'], [';', 'punctuation.terminator.statement.gmac'],
    ['join', 'keyword.control.gmac'], ['off', 'keyword.control.gmac'],
  ]);
});

test('a half-typed definition keeps colouring the lines after it', async () => {
  const tokens = await tokenize('define macro M as\n  inputs: { a : e3d.\n  performs: y = a gp\ndefine frame f as basis: {x} Euclidean end frame');
  assert.equal(innermost(tokens.find((t) => t.text === 'gp')), 'keyword.operator.word.gmac');
  assert.equal(innermost(tokens.find((t) => t.text === 'Euclidean')), 'keyword.other.gmac');
  assert.equal(innermost(tokens.find((t) => t.text === 'f')), 'entity.name.type.frame.gmac');
});
