// Shows that the TextMate grammar agrees with tree-sitter-rapid's highlight
// queries: every caret assertion of tree-sitter-rapid/test/highlight/*.mod
// (Neovim capture names, checked by `tree-sitter test`) is rewritten with the
// TextMate scope that stands for that capture, and the rewritten files are
// handed to vscode-tmgrammar-test. It also checks that the grammar's list of
// built-in types is the one in highlights.scm.
//
//   node test/agreement.mjs OUT_DIR   (then: vscode-tmgrammar-test "OUT_DIR/*.mod")
import * as fs from "node:fs";
import * as path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, "../../..");
const fixtures = path.join(repo, "tree-sitter-rapid/test/highlight");
const highlights = path.join(repo, "tree-sitter-rapid/queries/highlights.scm");
const grammarFile = path.join(here, "../syntaxes/rapid.tmLanguage.json");

// tree-sitter capture -> the TextMate scope that carries the same meaning.
export const SCOPE_OF_CAPTURE = {
  comment: "comment.line.exclamation.rapid",
  number: "constant.numeric.rapid",
  string: "string.quoted.double.rapid",
  "string.escape": "constant.character.escape.rapid",
  "string.special": "string.other.placeholder.rapid",
  "constant.builtin": "constant.language.boolean.rapid",
  keyword: "keyword.other.rapid",
  "keyword.function": "storage.type.function.rapid",
  "keyword.return": "keyword.control.return.rapid",
  "keyword.conditional": "keyword.control.conditional.rapid",
  "keyword.repeat": "keyword.control.loop.rapid",
  "keyword.exception": "keyword.control.exception.rapid",
  "keyword.modifier": "storage.modifier.rapid",
  "keyword.operator": "keyword.operator.word.rapid",
  operator: "keyword.operator.rapid",
  "variable.builtin": "variable.language.rapid",
  "punctuation.special": "punctuation.definition.header.rapid",
  attribute: "entity.other.attribute-name.rapid",
  constant: "variable.other.constant.rapid",
  module: "entity.name.namespace.rapid",
  "type.builtin": "support.type.rapid",
  type: "entity.name.type.rapid",
  "type.definition": "entity.name.type.definition.rapid",
  function: "entity.name.function.rapid",
  "function.call": "entity.name.function.call.rapid",
  "variable.parameter": "variable.parameter.rapid",
  property: "variable.other.property.rapid",
  variable: "variable.other.rapid",
  label: "entity.name.label.rapid",
};

function fail(message) {
  console.error(`agreement: ${message}`);
  process.exit(1);
}

const out = process.argv[2];
if (!out) {
  fail("usage: node test/agreement.mjs OUT_DIR");
}
fs.mkdirSync(out, { recursive: true });

// 1. Built-in types: the regex in highlights.scm against the grammar's list.
const query = fs.readFileSync(highlights, "utf8");
const match = /#match\? @type\.builtin "\^\(([^)]*)\)\$"/.exec(query);
if (!match) {
  fail("no @type.builtin #match? in highlights.scm");
}
const fromQuery = match[1]
  .split("|")
  .map((alt) => alt.replace(/\[(.)(.)\]/g, (_, a) => a.toLowerCase()))
  .sort();
const grammar = JSON.parse(fs.readFileSync(grammarFile, "utf8"));
const builtinPattern = JSON.stringify(grammar.repository).match(
  /"match":"\(\?i\)\\\\b\(([a-z|]+)\)\\\\b","name":"support\.type\.rapid"/,
);
if (!builtinPattern) {
  fail("no support.type.rapid pattern in the TextMate grammar");
}
const fromGrammar = builtinPattern[1].split("|").sort();
const missing = fromQuery.filter((t) => !fromGrammar.includes(t));
const extra = fromGrammar.filter((t) => !fromQuery.includes(t));
if (missing.length || extra.length) {
  fail(
    `built-in types differ: missing from the grammar [${missing}], not in highlights.scm [${extra}]`,
  );
}

// 2. Caret assertions, rewritten.
let count = 0;
const files = fs.readdirSync(fixtures).filter((f) => /\.(mod|sys|prg|modx|sysx)$/i.test(f));
if (files.length === 0) {
  fail(`no fixtures in ${fixtures}`);
}
for (const file of files) {
  const lines = fs.readFileSync(path.join(fixtures, file), "utf8").split(/\r?\n/);
  const rewritten = [`! SYNTAX TEST "source.rapid" "tree-sitter-rapid/test/highlight/${file}"`];
  for (const line of lines) {
    const assertion = /^(\s*!\s*(?:\^+|<-+)\s*)([A-Za-z.]+)\s*$/.exec(line);
    if (assertion && (line.includes("^") || line.includes("<-"))) {
      const scope = SCOPE_OF_CAPTURE[assertion[2]];
      if (!scope) {
        fail(`${file}: capture @${assertion[2]} has no TextMate scope in SCOPE_OF_CAPTURE`);
      }
      rewritten.push(assertion[1] + scope);
      count += 1;
    } else {
      rewritten.push(line);
    }
  }
  fs.writeFileSync(path.join(out, `ts-${file}`), rewritten.join("\n"));
}
console.log(
  `agreement: ${fromQuery.length} built-in types agree; ${count} tree-sitter assertions rewritten into ${out}`,
);
