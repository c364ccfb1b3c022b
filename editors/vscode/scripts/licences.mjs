// Writes LICENSE.txt for the .vsix from the repository's licence texts
// (the extension is under MIT OR Apache-2.0, as the rest of rapid): vsce
// runs this before packaging (`vscode:prepublish`).
import * as fs from "node:fs";
import * as path from "node:path";
import { fileURLToPath } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, "../../..");
const text = (name) => fs.readFileSync(path.join(repo, name), "utf8").trimEnd();

const licence = [
  "The ABB RAPID extension is part of rapid and is licensed under either of",
  "",
  "  * the MIT licence (below), or",
  "  * the Apache License, Version 2.0 (below),",
  "",
  "at your option.",
  "",
  "=".repeat(72),
  "MIT licence",
  "=".repeat(72),
  "",
  text("LICENSE-MIT"),
  "",
  "=".repeat(72),
  "Apache License, Version 2.0",
  "=".repeat(72),
  "",
  text("LICENSE-APACHE"),
  "",
].join("\n");
fs.writeFileSync(path.join(here, "..", "LICENSE.txt"), licence);
console.log("LICENSE.txt written from LICENSE-MIT and LICENSE-APACHE");
