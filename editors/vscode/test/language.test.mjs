// The language contribution: first-line detection, indentation rules and
// snippets. Run with `node --test test/`.
import assert from "node:assert/strict";
import * as fs from "node:fs";
import * as path from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const read = (file) => JSON.parse(fs.readFileSync(path.join(here, "..", file), "utf8"));
const pkg = read("package.json");
const config = read("language-configuration.json");
const language = pkg.contributes.languages.find((l) => l.id === "rapid");
const regex = (r) => (typeof r === "string" ? new RegExp(r) : new RegExp(r.pattern, r.flags));

test("extensions: every RAPID extension, lower and upper case", () => {
  for (const ext of ["mod", "modx", "sys", "sysx", "prg"]) {
    assert.ok(language.extensions.includes(`.${ext}`), ext);
    assert.ok(language.extensions.includes(`.${ext.toUpperCase()}`), ext);
  }
});

test("firstLine recognises RAPID modules and leaves other languages alone", () => {
  const firstLine = new RegExp(language.firstLine);
  for (const line of ["%%%", "MODULE MainModule", "module Cell(SYSMODULE, NOSTEPIN)", "\ufeffMODULE m", "  MODULE m ! main", "Module m(NOVIEW)"]) {
    assert.ok(firstLine.test(line), line);
  }
  for (const line of ["MODULE Lists;", "module example.com/x", "DEVICE=HIMEM.SYS", "; comment", "MODULE"]) {
    assert.ok(!firstLine.test(line), line);
  }
});

test("indentation: blocks open and their END words close, in any case", () => {
  const inc = regex(config.indentationRules.increaseIndentPattern);
  const dec = regex(config.indentationRules.decreaseIndentPattern);
  const opens = [
    "MODULE m", "PROC main()", "LOCAL PROC p(num x)", "FUNC num f(num x)", "TRAP t", "RECORD r",
    "IF x > 1 THEN", "ELSEIF y THEN", "ELSE", "FOR i FROM 1 TO 3 DO", "WHILE TRUE DO", "TEST n",
    "CASE 1, 2:", "DEFAULT:", "ERROR", "UNDO", "BACKWARD", "  if x then", "  proc lower()",
  ];
  for (const line of opens) assert.ok(inc.test(line), `should indent after: ${line}`);
  const stays = ["x := 1;", "IF x Stop;", "MoveL p, v100, fine, tool0;", "ENDIF", "! IF x THEN", "ERRNO := 1;"];
  for (const line of stays) assert.ok(!inc.test(line), `should not indent after: ${line}`);
  const closes = ["ENDPROC", "  ENDFUNC", "ENDTRAP", "ENDRECORD", "ENDIF", "ENDFOR", "ENDWHILE", "ENDTEST", "ENDMODULE", "ELSE", "ELSEIF x THEN", "CASE 3:", "DEFAULT:", "ERROR", "  endif"];
  for (const line of closes) assert.ok(dec.test(line), `should outdent: ${line}`);
  for (const line of ["ENDING := 1;", "ERRNO := 1;", "x := 1;"]) assert.ok(!dec.test(line), `should not outdent: ${line}`);
});

test("comments, brackets and auto-closing", () => {
  assert.equal(config.comments.lineComment, "!");
  assert.deepEqual(config.brackets, [["[", "]"], ["{", "}"], ["(", ")"]]);
  for (const open of ["[", "{", "(", '"']) {
    assert.ok(config.autoClosingPairs.some((p) => p.open === open), open);
  }
});

test("snippets: every body is non-empty and placeholders are balanced", () => {
  const snippets = read("snippets/rapid.json");
  const prefixes = new Set();
  for (const [name, s] of Object.entries(snippets)) {
    assert.ok(s.prefix && s.body.length > 0 && s.description, name);
    assert.ok(!prefixes.has(s.prefix), `duplicate prefix ${s.prefix}`);
    prefixes.add(s.prefix);
    const body = s.body.join("\n");
    let depth = 0;
    for (const m of body.matchAll(/\$\{|\}/g)) {
      depth += m[0] === "${" ? 1 : -1;
      assert.ok(depth >= 0, `${name}: unbalanced placeholder`);
    }
    assert.equal(depth, 0, `${name}: unbalanced placeholder`);
  }
  for (const p of ["proc", "func", "trap", "record", "if", "for", "while", "test", "movel", "movej", "movec", "moveabsj"]) {
    assert.ok(prefixes.has(p), p);
  }
});
