// The workspace that the editors' end-to-end tests open: a copy of
// examples/palletizer (two modules and an EIO.cfg) with one seeded error and
// a constant whose value hovers show.
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

/** Creates the workspace in `dest` (which must not exist); returns the seeded file. */
export function makeWorkspace(dest) {
  fs.cpSync(path.join(repo, "examples/palletizer"), dest, { recursive: true });
  const main = path.join(dest, "MainModule.mod");
  let text = fs.readFileSync(main, "latin1");
  for (const [from, to] of EDITS) {
    if (!text.includes(from)) {
      throw new Error(`examples/palletizer/MainModule.mod changed: cannot find ${JSON.stringify(from)}`);
    }
    text = text.replace(from, to);
  }
  fs.writeFileSync(main, text, "latin1");
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
