;; Generated from tree-sitter-rapid/queries/locals.scm by editors/sync-queries.sh: do not edit.

; Scopes, definitions and references for ABB RAPID.
; Names are case-insensitive in RAPID; editors that compare text exactly
; will miss references spelled in another case.

(module) @local.scope

(procedure_declaration) @local.scope

(function_declaration) @local.scope

(trap_declaration) @local.scope

; the loop variable of a FOR exists only inside the loop
(for_statement) @local.scope

(procedure_declaration
  name: (identifier) @local.definition.function)

(function_declaration
  name: (identifier) @local.definition.function)

(trap_declaration
  name: (identifier) @local.definition.function)

(data_declaration
  name: (identifier) @local.definition.var)

(parameter
  name: (identifier) @local.definition.parameter)

(record_declaration
  name: (identifier) @local.definition.type)

(alias_declaration
  name: (identifier) @local.definition.type)

(record_component
  name: (identifier) @local.definition.field)

(for_statement
  variable: (identifier) @local.definition.var)

(label
  name: (identifier) @local.definition.label)

(identifier) @local.reference
