;; Generated from tree-sitter-rapid/queries/folds.scm by editors/sync-queries.sh: do not edit.

; Folding ranges for ABB RAPID.

[
  (module)
  (module_header)
  (record_declaration)
  (procedure_declaration)
  (function_declaration)
  (trap_declaration)
  (backward_handler)
  (error_handler)
  (undo_handler)
  (if_statement)
  (elseif_clause)
  (else_clause)
  (for_statement)
  (while_statement)
  (test_statement)
  (test_case)
  (default_case)
  (aggregate)
] @fold
