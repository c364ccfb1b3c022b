;; Generated from tree-sitter-rapid/queries/indents.scm by editors/sync-queries.sh: do not edit.

; Indentation for ABB RAPID (nvim-treesitter conventions).

[
  (module)
  (record_declaration)
  (procedure_declaration)
  (function_declaration)
  (trap_declaration)
  (if_statement)
  (for_statement)
  (while_statement)
  (test_statement)
  (aggregate)
  (parameter_list)
  (argument_list)
] @indent.begin

[
  "endmodule"
  "endrecord"
  "endproc"
  "endfunc"
  "endtrap"
  "endif"
  "endfor"
  "endwhile"
  "endtest"
  "]"
  ")"
] @indent.end

[
  "endmodule"
  "endrecord"
  "endproc"
  "endfunc"
  "endtrap"
  "endif"
  "endfor"
  "endwhile"
  "endtest"
  "elseif"
  "else"
  "case"
  "default"
  "backward"
  "error"
  "undo"
  "]"
  ")"
] @indent.branch

(comment) @indent.auto
