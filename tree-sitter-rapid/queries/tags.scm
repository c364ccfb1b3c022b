; Symbols for code navigation in ABB RAPID.

(module
  name: (identifier) @name) @definition.module

(procedure_declaration
  name: (identifier) @name) @definition.function

(function_declaration
  name: (identifier) @name) @definition.function

(trap_declaration
  name: (identifier) @name) @definition.function

(record_declaration
  name: (identifier) @name) @definition.type

(alias_declaration
  name: (identifier) @name) @definition.type

(data_declaration
  storage: "const"
  name: (identifier) @name) @definition.constant

(data_declaration
  storage: ["var" "pers"]
  name: (identifier) @name) @definition.variable

(procedure_call
  name: (identifier) @name) @reference.call

(function_call
  name: (identifier) @name) @reference.call

(type_identifier) @name @reference.type
