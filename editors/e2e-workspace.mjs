// The workspace that the editors' end-to-end tests open: a copy of
// examples/palletizer (two modules and an EIO.cfg) with one seeded error, a
// constant whose value hovers show, and a seeded warning in Cell.sys (a file
// the tests do not open: the editor must show it all the same).
//
//   node editors/e2e-workspace.mjs DEST      (prints DEST/MainModule.mod)
import * as fs from "node:fs";
import * as path from "node:path";
import { fileURLToPath } from "node:url";

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");

export const EDITS = [
  // a constant whose value the hover shows: 3 * 4 * 2
  ["    CONST num pitchY := 160;\n", "    CONST num pitchY := 160;\n    CONST num nSlots := nRows * nCols * nLayers;\n"],
  [
    '        TPWrite "Pallet complete: " \\Num:=nPlaced;\n',
    '        TPWrite "Pallet complete: " \\Num:=nPlaced;\n        TPWrite "Slots: " \\Num:=nSlots;\n',
  ],
  // the seeded error: a string assigned to a num
  ["    PROC GoHome()\n", '    PROC GoHome()\n        nPlaced := "none";\n'],
];

export const CELL_EDITS = [
  // the seeded warning of a file that is not open: an unused routine datum
  ["\nENDMODULE", "\n    PROC CheckCell()\n        VAR num nUnchecked;\n    ENDPROC\n\nENDMODULE"],
];

function edit(file, edits) {
  let text = fs.readFileSync(file, "latin1");
  for (const [from, to] of edits) {
    if (!text.includes(from)) {
      throw new Error(`${file} changed: cannot find ${JSON.stringify(from)}`);
    }
    text = text.replace(from, to);
  }
  fs.writeFileSync(file, text, "latin1");
}

/** Creates the workspace in `dest` (which must not exist); returns the seeded file. */
export function makeWorkspace(dest) {
  fs.cpSync(path.join(repo, "examples/palletizer"), dest, { recursive: true });
  const main = path.join(dest, "MainModule.mod");
  edit(main, EDITS);
  edit(path.join(dest, "Cell.sys"), CELL_EDITS);
  return main;
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const dest = process.argv[2];
  if (!dest) {
    console.error("usage: node editors/e2e-workspace.mjs DEST");
    process.exit(2);
  }
  console.log(makeWorkspace(path.resolve(dest)));
}
