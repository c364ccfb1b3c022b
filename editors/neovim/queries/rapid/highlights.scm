;; Generated from tree-sitter-rapid/queries/highlights.scm by editors/sync-queries.sh: do not edit.

; Syntax highlighting for ABB RAPID, with Neovim capture names.
; No two patterns capture the same node, so the result does not depend on
; whether an editor lets the first or the last matching pattern win.

(comment) @comment @spell

(trailing_text) @comment

(number) @number

(string) @string

(escape_sequence) @string.escape

(boolean) @constant.builtin

(placeholder) @string.special

; ---------------------------------------------------------------- keywords

[
  "module"
  "endmodule"
  "record"
  "endrecord"
  "alias"
  "with"
  "connect"
] @keyword

[
  "proc"
  "endproc"
  "func"
  "endfunc"
  "trap"
  "endtrap"
] @keyword.function

[
  "return"
] @keyword.return

[
  "if"
  "then"
  "elseif"
  "else"
  "endif"
  "test"
  "case"
  "default"
  "endtest"
] @keyword.conditional

[
  "for"
  "from"
  "to"
  "step"
  "do"
  "endfor"
  "while"
  "endwhile"
  "exit"
  "goto"
] @keyword.repeat

[
  "error"
  "undo"
  "backward"
  "raise"
  "retry"
  "trynext"
] @keyword.exception

[
  "local"
  "task"
  "var"
  "pers"
  "const"
  "inout"
] @keyword.modifier

(module_attribute) @keyword.modifier

[
  "and"
  "or"
  "xor"
  "not"
  "div"
  "mod"
] @keyword.operator

; ---------------------------------------------------------------- operators

[
  ":="
  "="
  "<>"
  "<"
  ">"
  "<="
  ">="
  "+"
  "-"
  "/"
  "\\"
  "?"
  "|"
  "%"
] @operator

(binary_expression
  operator: "*" @operator)

(parameter_dimensions
  "*" @operator)

(star) @variable.builtin

[
  "("
  ")"
  "["
  "]"
  "{"
  "}"
] @punctuation.bracket

[
  ","
  ";"
  "."
  ":"
] @punctuation.delimiter

"%%%" @punctuation.special

; ---------------------------------------------------------------- names

(header_entry
  key: (identifier) @attribute)

(header_value) @constant

(module
  name: (identifier) @module)

((type_identifier) @type.builtin
  (#match? @type.builtin "^([nN][uU][mM]|[dD][nN][uU][mM]|[bB][oO][oO][lL]|[sS][tT][rR][iI][nN][gG]|[bB][yY][tT][eE]|[sS][wW][iI][tT][cC][hH]|[pP][oO][sS]|[oO][rR][iI][eE][nN][tT]|[pP][oO][sS][eE]|[cC][oO][nN][fF][dD][aA][tT][aA]|[eE][xX][tT][jJ][oO][iI][nN][tT]|[rR][oO][bB][tT][aA][rR][gG][eE][tT]|[jJ][oO][iI][nN][tT][tT][aA][rR][gG][eE][tT]|[rR][oO][bB][jJ][oO][iI][nN][tT]|[sS][pP][eE][eE][dD][dD][aA][tT][aA]|[zZ][oO][nN][eE][dD][aA][tT][aA]|[tT][oO][oO][lL][dD][aA][tT][aA]|[wW][oO][bB][jJ][dD][aA][tT][aA]|[lL][oO][aA][dD][dD][aA][tT][aA]|[iI][nN][tT][nN][uU][mM]|[cC][lL][oO][cC][kK]|[eE][rR][rR][nN][uU][mM]|[sS][iI][gG][nN][aA][lL][dD][iI]|[sS][iI][gG][nN][aA][lL][dD][oO]|[sS][iI][gG][nN][aA][lL][aA][iI]|[sS][iI][gG][nN][aA][lL][aA][oO]|[sS][iI][gG][nN][aA][lL][gG][iI]|[sS][iI][gG][nN][aA][lL][gG][oO]|[iI][oO][dD][eE][vV]|[rR][aA][wW][bB][yY][tT][eE][sS]|[sS][oO][cC][kK][eE][tT][dD][eE][vV]|[tT][rR][iI][gG][gG][dD][aA][tT][aA]|[sS][tT][oO][pP][mM][oO][tT][iI][oO][nN][dD][aA][tT][aA]|[mM][eE][cC][uU][nN][iI][tT]|[tT][aA][sS][kK][iI][dD]|[tT][eE][sS][tT][sS][iI][gG][nN][aA][lL]|[wW][zZ][sS][tT][aA][tT][iI][oO][nN][aA][rR][yY]|[wW][zZ][tT][eE][mM][pP][oO][rR][aA][rR][yY]|[sS][hH][aA][pP][eE][dD][aA][tT][aA]|[eE][rR][rR][dD][oO][mM][aA][iI][nN]|[eE][rR][rR][tT][yY][pP][eE]|[oO][pP][nN][uU][mM]|[dD][aA][tT][aA][pP][oO][sS]|[bB][tT][nN][rR][eE][sS]|[lL][iI][sS][tT][iI][tT][eE][mM]|[tT][pP][nN][uU][mM]|[cC][fF][gG][dD][oO][mM][aA][iI][nN])$"))

((type_identifier) @type
  (#not-match? @type "^([nN][uU][mM]|[dD][nN][uU][mM]|[bB][oO][oO][lL]|[sS][tT][rR][iI][nN][gG]|[bB][yY][tT][eE]|[sS][wW][iI][tT][cC][hH]|[pP][oO][sS]|[oO][rR][iI][eE][nN][tT]|[pP][oO][sS][eE]|[cC][oO][nN][fF][dD][aA][tT][aA]|[eE][xX][tT][jJ][oO][iI][nN][tT]|[rR][oO][bB][tT][aA][rR][gG][eE][tT]|[jJ][oO][iI][nN][tT][tT][aA][rR][gG][eE][tT]|[rR][oO][bB][jJ][oO][iI][nN][tT]|[sS][pP][eE][eE][dD][dD][aA][tT][aA]|[zZ][oO][nN][eE][dD][aA][tT][aA]|[tT][oO][oO][lL][dD][aA][tT][aA]|[wW][oO][bB][jJ][dD][aA][tT][aA]|[lL][oO][aA][dD][dD][aA][tT][aA]|[iI][nN][tT][nN][uU][mM]|[cC][lL][oO][cC][kK]|[eE][rR][rR][nN][uU][mM]|[sS][iI][gG][nN][aA][lL][dD][iI]|[sS][iI][gG][nN][aA][lL][dD][oO]|[sS][iI][gG][nN][aA][lL][aA][iI]|[sS][iI][gG][nN][aA][lL][aA][oO]|[sS][iI][gG][nN][aA][lL][gG][iI]|[sS][iI][gG][nN][aA][lL][gG][oO]|[iI][oO][dD][eE][vV]|[rR][aA][wW][bB][yY][tT][eE][sS]|[sS][oO][cC][kK][eE][tT][dD][eE][vV]|[tT][rR][iI][gG][gG][dD][aA][tT][aA]|[sS][tT][oO][pP][mM][oO][tT][iI][oO][nN][dD][aA][tT][aA]|[mM][eE][cC][uU][nN][iI][tT]|[tT][aA][sS][kK][iI][dD]|[tT][eE][sS][tT][sS][iI][gG][nN][aA][lL]|[wW][zZ][sS][tT][aA][tT][iI][oO][nN][aA][rR][yY]|[wW][zZ][tT][eE][mM][pP][oO][rR][aA][rR][yY]|[sS][hH][aA][pP][eE][dD][aA][tT][aA]|[eE][rR][rR][dD][oO][mM][aA][iI][nN]|[eE][rR][rR][tT][yY][pP][eE]|[oO][pP][nN][uU][mM]|[dD][aA][tT][aA][pP][oO][sS]|[bB][tT][nN][rR][eE][sS]|[lL][iI][sS][tT][iI][tT][eE][mM]|[tT][pP][nN][uU][mM]|[cC][fF][gG][dD][oO][mM][aA][iI][nN])$"))

(procedure_declaration
  name: (identifier) @function)

(function_declaration
  name: (identifier) @function)

(trap_declaration
  name: (identifier) @function)

(procedure_call
  name: (identifier) @function.call)

(function_call
  name: (identifier) @function.call)

(connect_statement
  trap: (identifier) @function)

(parameter
  name: (identifier) @variable.parameter)

(argument
  name: (identifier) @variable.parameter)

(record_declaration
  name: (identifier) @type.definition)

(alias_declaration
  name: (identifier) @type.definition)

(record_component
  name: (identifier) @property)

(component_access
  component: (identifier) @property)

(data_declaration
  storage: "const"
  name: (identifier) @constant)

(data_declaration
  storage: ["var" "pers"]
  name: (identifier) @variable)

(label
  name: (identifier) @label)

(goto_statement
  label: (identifier) @label)

; identifiers used as values

(assignment
  left: (identifier) @variable)

(assignment
  right: (identifier) @variable)

(binary_expression
  left: (identifier) @variable)

(binary_expression
  right: (identifier) @variable)

(unary_expression
  operand: (identifier) @variable)

(parenthesized_expression
  expression: (identifier) @variable)

(component_access
  object: (identifier) @variable)

(index_expression
  object: (identifier) @variable)

(index_expression
  index: (identifier) @variable)

(aggregate
  element: (identifier) @variable)

(argument
  value: (identifier) @variable)

(argument
  conditional: (identifier) @variable)

(data_declaration
  value: (identifier) @variable)

(dimension_list
  dimension: (identifier) @variable)

(if_statement
  condition: (identifier) @variable)

(elseif_clause
  condition: (identifier) @variable)

(compact_if_statement
  condition: (identifier) @variable)

(while_statement
  condition: (identifier) @variable)

(for_statement
  variable: (identifier) @variable)

(for_statement
  from: (identifier) @variable)

(for_statement
  to: (identifier) @variable)

(for_statement
  step: (identifier) @variable)

(test_statement
  value: (identifier) @variable)

(test_case
  value: (identifier) @variable)

(return_statement
  value: (identifier) @variable)

(raise_statement
  value: (identifier) @variable)

(error_handler
  error: (identifier) @variable)

(connect_statement
  interrupt: (identifier) @variable)

(late_binding
  expression: (identifier) @variable)
