//! Node kinds and field names of the RAPID grammar.
//!
//! GENERATED from `tree-sitter-rapid/src/node-types.json`: do not edit.
//! After `tree-sitter generate`, rewrite it with
//! `UPDATE_EXPECT=1 cargo test -p rapid-analyzer --test syntax`;
//! that test fails while this file is stale.

/// The named node kinds (`Node::kind` of a named node).
pub mod kind {
    /// `aggregate`, with fields `element`.
    pub const AGGREGATE: &str = "aggregate";
    /// `alias_declaration`, with fields `name`, `scope`, `type`.
    pub const ALIAS_DECLARATION: &str = "alias_declaration";
    /// `argument`, with fields `conditional`, `name`, `value`.
    pub const ARGUMENT: &str = "argument";
    /// `argument_list`, with fields `argument`.
    pub const ARGUMENT_LIST: &str = "argument_list";
    /// `assignment`, with fields `left`, `right`.
    pub const ASSIGNMENT: &str = "assignment";
    /// `backward_handler`, with fields `body`.
    pub const BACKWARD_HANDLER: &str = "backward_handler";
    /// `binary_expression`, with fields `left`, `operator`, `right`.
    pub const BINARY_EXPRESSION: &str = "binary_expression";
    /// `boolean`.
    pub const BOOLEAN: &str = "boolean";
    /// `comment`.
    pub const COMMENT: &str = "comment";
    /// `compact_if_statement`, with fields `body`, `condition`.
    pub const COMPACT_IF_STATEMENT: &str = "compact_if_statement";
    /// `component_access`, with fields `component`, `object`.
    pub const COMPONENT_ACCESS: &str = "component_access";
    /// `connect_statement`, with fields `interrupt`, `trap`.
    pub const CONNECT_STATEMENT: &str = "connect_statement";
    /// `data_declaration`, with fields `dimensions`, `name`, `scope`, `storage`, `type`, `value`.
    pub const DATA_DECLARATION: &str = "data_declaration";
    /// `default_case`, with fields `body`.
    pub const DEFAULT_CASE: &str = "default_case";
    /// `dimension_list`, with fields `dimension`.
    pub const DIMENSION_LIST: &str = "dimension_list";
    /// `else_clause`, with fields `body`.
    pub const ELSE_CLAUSE: &str = "else_clause";
    /// `elseif_clause`, with fields `body`, `condition`.
    pub const ELSEIF_CLAUSE: &str = "elseif_clause";
    /// `error_handler`, with fields `body`, `error`.
    pub const ERROR_HANDLER: &str = "error_handler";
    /// `escape_sequence`.
    pub const ESCAPE_SEQUENCE: &str = "escape_sequence";
    /// `exit_statement`.
    pub const EXIT_STATEMENT: &str = "exit_statement";
    /// `for_statement`, with fields `body`, `from`, `step`, `to`, `variable`.
    pub const FOR_STATEMENT: &str = "for_statement";
    /// `function_call`, with fields `arguments`, `name`.
    pub const FUNCTION_CALL: &str = "function_call";
    /// `function_declaration`, with fields `backward`, `body`, `error`, `name`, `parameters`, `scope`, `type`, `undo`.
    pub const FUNCTION_DECLARATION: &str = "function_declaration";
    /// `goto_statement`, with fields `label`.
    pub const GOTO_STATEMENT: &str = "goto_statement";
    /// `header_entry`, with fields `key`, `value`.
    pub const HEADER_ENTRY: &str = "header_entry";
    /// `header_value`.
    pub const HEADER_VALUE: &str = "header_value";
    /// `identifier`.
    pub const IDENTIFIER: &str = "identifier";
    /// `if_statement`, with fields `alternative`, `body`, `condition`.
    pub const IF_STATEMENT: &str = "if_statement";
    /// `index_expression`, with fields `index`, `object`.
    pub const INDEX_EXPRESSION: &str = "index_expression";
    /// `label`, with fields `name`.
    pub const LABEL: &str = "label";
    /// `late_binding`, with fields `expression`.
    pub const LATE_BINDING: &str = "late_binding";
    /// `module`, with fields `attributes`, `body`, `header`, `name`.
    pub const MODULE: &str = "module";
    /// `module_attribute`.
    pub const MODULE_ATTRIBUTE: &str = "module_attribute";
    /// `module_attributes`, with fields `attribute`.
    pub const MODULE_ATTRIBUTES: &str = "module_attributes";
    /// `module_header`, with fields `entry`.
    pub const MODULE_HEADER: &str = "module_header";
    /// `number`.
    pub const NUMBER: &str = "number";
    /// `optional_parameter`, with fields `alternative`.
    pub const OPTIONAL_PARAMETER: &str = "optional_parameter";
    /// `parameter`, with fields `dimensions`, `mode`, `name`, `type`.
    pub const PARAMETER: &str = "parameter";
    /// `parameter_dimensions`, with fields `dimension`.
    pub const PARAMETER_DIMENSIONS: &str = "parameter_dimensions";
    /// `parameter_list`, with fields `parameter`.
    pub const PARAMETER_LIST: &str = "parameter_list";
    /// `parenthesized_expression`, with fields `expression`.
    pub const PARENTHESIZED_EXPRESSION: &str = "parenthesized_expression";
    /// `placeholder`.
    pub const PLACEHOLDER: &str = "placeholder";
    /// `procedure_call`, with fields `arguments`, `name`.
    pub const PROCEDURE_CALL: &str = "procedure_call";
    /// `procedure_declaration`, with fields `backward`, `body`, `error`, `name`, `parameters`, `scope`, `undo`.
    pub const PROCEDURE_DECLARATION: &str = "procedure_declaration";
    /// `raise_statement`, with fields `value`.
    pub const RAISE_STATEMENT: &str = "raise_statement";
    /// `record_component`, with fields `name`, `type`.
    pub const RECORD_COMPONENT: &str = "record_component";
    /// `record_declaration`, with fields `component`, `name`, `scope`.
    pub const RECORD_DECLARATION: &str = "record_declaration";
    /// `retry_statement`.
    pub const RETRY_STATEMENT: &str = "retry_statement";
    /// `return_statement`, with fields `value`.
    pub const RETURN_STATEMENT: &str = "return_statement";
    /// `source_file`.
    pub const SOURCE_FILE: &str = "source_file";
    /// `star`.
    pub const STAR: &str = "star";
    /// `string`.
    pub const STRING: &str = "string";
    /// `string_content`.
    pub const STRING_CONTENT: &str = "string_content";
    /// `test_case`, with fields `body`, `value`.
    pub const TEST_CASE: &str = "test_case";
    /// `test_statement`, with fields `case`, `default`, `value`.
    pub const TEST_STATEMENT: &str = "test_statement";
    /// `trailing_text`.
    pub const TRAILING_TEXT: &str = "trailing_text";
    /// `trap_declaration`, with fields `backward`, `body`, `error`, `name`, `scope`, `undo`.
    pub const TRAP_DECLARATION: &str = "trap_declaration";
    /// `trynext_statement`.
    pub const TRYNEXT_STATEMENT: &str = "trynext_statement";
    /// `type_identifier`.
    pub const TYPE_IDENTIFIER: &str = "type_identifier";
    /// `unary_expression`, with fields `operand`, `operator`.
    pub const UNARY_EXPRESSION: &str = "unary_expression";
    /// `undo_handler`, with fields `body`.
    pub const UNDO_HANDLER: &str = "undo_handler";
    /// `while_statement`, with fields `body`, `condition`.
    pub const WHILE_STATEMENT: &str = "while_statement";
}

/// The field names (`Node::child_by_field_name`).
pub mod field {
    /// `alternative`, in `if_statement`, `optional_parameter`.
    pub const ALTERNATIVE: &str = "alternative";
    /// `argument`, in `argument_list`.
    pub const ARGUMENT: &str = "argument";
    /// `arguments`, in `function_call`, `procedure_call`.
    pub const ARGUMENTS: &str = "arguments";
    /// `attribute`, in `module_attributes`.
    pub const ATTRIBUTE: &str = "attribute";
    /// `attributes`, in `module`.
    pub const ATTRIBUTES: &str = "attributes";
    /// `backward`, in `function_declaration`, `procedure_declaration`, `trap_declaration`.
    pub const BACKWARD: &str = "backward";
    /// `body`, in `backward_handler`, `compact_if_statement`, `default_case`, `else_clause`, `elseif_clause`, `error_handler`, `for_statement`, `function_declaration`, `if_statement`, `module`, `procedure_declaration`, `test_case`, `trap_declaration`, `undo_handler`, `while_statement`.
    pub const BODY: &str = "body";
    /// `case`, in `test_statement`.
    pub const CASE: &str = "case";
    /// `component`, in `component_access`, `record_declaration`.
    pub const COMPONENT: &str = "component";
    /// `condition`, in `compact_if_statement`, `elseif_clause`, `if_statement`, `while_statement`.
    pub const CONDITION: &str = "condition";
    /// `conditional`, in `argument`.
    pub const CONDITIONAL: &str = "conditional";
    /// `default`, in `test_statement`.
    pub const DEFAULT: &str = "default";
    /// `dimension`, in `dimension_list`, `parameter_dimensions`.
    pub const DIMENSION: &str = "dimension";
    /// `dimensions`, in `data_declaration`, `parameter`.
    pub const DIMENSIONS: &str = "dimensions";
    /// `element`, in `aggregate`.
    pub const ELEMENT: &str = "element";
    /// `entry`, in `module_header`.
    pub const ENTRY: &str = "entry";
    /// `error`, in `error_handler`, `function_declaration`, `procedure_declaration`, `trap_declaration`.
    pub const ERROR: &str = "error";
    /// `expression`, in `late_binding`, `parenthesized_expression`.
    pub const EXPRESSION: &str = "expression";
    /// `from`, in `for_statement`.
    pub const FROM: &str = "from";
    /// `header`, in `module`.
    pub const HEADER: &str = "header";
    /// `index`, in `index_expression`.
    pub const INDEX: &str = "index";
    /// `interrupt`, in `connect_statement`.
    pub const INTERRUPT: &str = "interrupt";
    /// `key`, in `header_entry`.
    pub const KEY: &str = "key";
    /// `label`, in `goto_statement`.
    pub const LABEL: &str = "label";
    /// `left`, in `assignment`, `binary_expression`.
    pub const LEFT: &str = "left";
    /// `mode`, in `parameter`.
    pub const MODE: &str = "mode";
    /// `name`, in `alias_declaration`, `argument`, `data_declaration`, `function_call`, `function_declaration`, `label`, `module`, `parameter`, `procedure_call`, `procedure_declaration`, `record_component`, `record_declaration`, `trap_declaration`.
    pub const NAME: &str = "name";
    /// `object`, in `component_access`, `index_expression`.
    pub const OBJECT: &str = "object";
    /// `operand`, in `unary_expression`.
    pub const OPERAND: &str = "operand";
    /// `operator`, in `binary_expression`, `unary_expression`.
    pub const OPERATOR: &str = "operator";
    /// `parameter`, in `parameter_list`.
    pub const PARAMETER: &str = "parameter";
    /// `parameters`, in `function_declaration`, `procedure_declaration`.
    pub const PARAMETERS: &str = "parameters";
    /// `right`, in `assignment`, `binary_expression`.
    pub const RIGHT: &str = "right";
    /// `scope`, in `alias_declaration`, `data_declaration`, `function_declaration`, `procedure_declaration`, `record_declaration`, `trap_declaration`.
    pub const SCOPE: &str = "scope";
    /// `step`, in `for_statement`.
    pub const STEP: &str = "step";
    /// `storage`, in `data_declaration`.
    pub const STORAGE: &str = "storage";
    /// `to`, in `for_statement`.
    pub const TO: &str = "to";
    /// `trap`, in `connect_statement`.
    pub const TRAP: &str = "trap";
    /// `type`, in `alias_declaration`, `data_declaration`, `function_declaration`, `parameter`, `record_component`.
    pub const TYPE: &str = "type";
    /// `undo`, in `function_declaration`, `procedure_declaration`, `trap_declaration`.
    pub const UNDO: &str = "undo";
    /// `value`, in `argument`, `data_declaration`, `header_entry`, `raise_statement`, `return_statement`, `test_case`, `test_statement`.
    pub const VALUE: &str = "value";
    /// `variable`, in `for_statement`.
    pub const VARIABLE: &str = "variable";
}

/// Every named node kind, sorted.
pub const NAMED_KINDS: &[&str] = &[
    kind::AGGREGATE,
    kind::ALIAS_DECLARATION,
    kind::ARGUMENT,
    kind::ARGUMENT_LIST,
    kind::ASSIGNMENT,
    kind::BACKWARD_HANDLER,
    kind::BINARY_EXPRESSION,
    kind::BOOLEAN,
    kind::COMMENT,
    kind::COMPACT_IF_STATEMENT,
    kind::COMPONENT_ACCESS,
    kind::CONNECT_STATEMENT,
    kind::DATA_DECLARATION,
    kind::DEFAULT_CASE,
    kind::DIMENSION_LIST,
    kind::ELSE_CLAUSE,
    kind::ELSEIF_CLAUSE,
    kind::ERROR_HANDLER,
    kind::ESCAPE_SEQUENCE,
    kind::EXIT_STATEMENT,
    kind::FOR_STATEMENT,
    kind::FUNCTION_CALL,
    kind::FUNCTION_DECLARATION,
    kind::GOTO_STATEMENT,
    kind::HEADER_ENTRY,
    kind::HEADER_VALUE,
    kind::IDENTIFIER,
    kind::IF_STATEMENT,
    kind::INDEX_EXPRESSION,
    kind::LABEL,
    kind::LATE_BINDING,
    kind::MODULE,
    kind::MODULE_ATTRIBUTE,
    kind::MODULE_ATTRIBUTES,
    kind::MODULE_HEADER,
    kind::NUMBER,
    kind::OPTIONAL_PARAMETER,
    kind::PARAMETER,
    kind::PARAMETER_DIMENSIONS,
    kind::PARAMETER_LIST,
    kind::PARENTHESIZED_EXPRESSION,
    kind::PLACEHOLDER,
    kind::PROCEDURE_CALL,
    kind::PROCEDURE_DECLARATION,
    kind::RAISE_STATEMENT,
    kind::RECORD_COMPONENT,
    kind::RECORD_DECLARATION,
    kind::RETRY_STATEMENT,
    kind::RETURN_STATEMENT,
    kind::SOURCE_FILE,
    kind::STAR,
    kind::STRING,
    kind::STRING_CONTENT,
    kind::TEST_CASE,
    kind::TEST_STATEMENT,
    kind::TRAILING_TEXT,
    kind::TRAP_DECLARATION,
    kind::TRYNEXT_STATEMENT,
    kind::TYPE_IDENTIFIER,
    kind::UNARY_EXPRESSION,
    kind::UNDO_HANDLER,
    kind::WHILE_STATEMENT,
];

/// Every anonymous node kind (keywords in lower case, punctuation), sorted.
pub const TOKENS: &[&str] = &[
    "\"",
    "%",
    "%%%",
    "(",
    ")",
    "*",
    "+",
    ",",
    "-",
    ".",
    "/",
    ":",
    ":=",
    ";",
    "<",
    "<=",
    "<>",
    "<CSE>",
    "<EIT>",
    "=",
    ">",
    ">=",
    "?",
    "[",
    "\\",
    "]",
    "alias",
    "and",
    "backward",
    "case",
    "connect",
    "const",
    "default",
    "div",
    "do",
    "else",
    "elseif",
    "endfor",
    "endfunc",
    "endif",
    "endmodule",
    "endproc",
    "endrecord",
    "endtest",
    "endtrap",
    "endwhile",
    "error",
    "exit",
    "false",
    "for",
    "from",
    "func",
    "goto",
    "if",
    "inout",
    "local",
    "mod",
    "module",
    "nostepin",
    "not",
    "noview",
    "or",
    "pers",
    "proc",
    "raise",
    "readonly",
    "record",
    "retry",
    "return",
    "step",
    "sysmodule",
    "task",
    "test",
    "then",
    "to",
    "trap",
    "true",
    "trynext",
    "undo",
    "var",
    "viewonly",
    "while",
    "with",
    "xor",
    "{",
    "|",
    "}",
];

/// Every field name, sorted.
pub const FIELDS: &[&str] = &[
    field::ALTERNATIVE,
    field::ARGUMENT,
    field::ARGUMENTS,
    field::ATTRIBUTE,
    field::ATTRIBUTES,
    field::BACKWARD,
    field::BODY,
    field::CASE,
    field::COMPONENT,
    field::CONDITION,
    field::CONDITIONAL,
    field::DEFAULT,
    field::DIMENSION,
    field::DIMENSIONS,
    field::ELEMENT,
    field::ENTRY,
    field::ERROR,
    field::EXPRESSION,
    field::FROM,
    field::HEADER,
    field::INDEX,
    field::INTERRUPT,
    field::KEY,
    field::LABEL,
    field::LEFT,
    field::MODE,
    field::NAME,
    field::OBJECT,
    field::OPERAND,
    field::OPERATOR,
    field::PARAMETER,
    field::PARAMETERS,
    field::RIGHT,
    field::SCOPE,
    field::STEP,
    field::STORAGE,
    field::TO,
    field::TRAP,
    field::TYPE,
    field::UNDO,
    field::VALUE,
    field::VARIABLE,
];

/// A field of a node kind: its name, whether it can hold several nodes or
/// must hold one, and the kinds it holds (named ones as they are, anonymous
/// ones too: keywords in lower case).
#[derive(Debug, Clone, Copy)]
pub struct FieldInfo {
    pub name: &'static str,
    pub multiple: bool,
    pub required: bool,
    pub kinds: &'static [&'static str],
}

/// The fields of each named kind that has fields, sorted by kind.
pub const KIND_FIELDS: &[(&str, &[FieldInfo])] = &[
    (
        kind::AGGREGATE,
        &[
            FieldInfo {
                name: field::ELEMENT,
                multiple: true,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::ALIAS_DECLARATION,
        &[
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
            FieldInfo {
                name: field::TYPE,
                multiple: false,
                required: true,
                kinds: &[kind::PLACEHOLDER, kind::TYPE_IDENTIFIER],
            },
        ],
    ),
    (
        kind::ARGUMENT,
        &[
            FieldInfo {
                name: field::CONDITIONAL,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: false,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STAR, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::ARGUMENT_LIST,
        &[
            FieldInfo {
                name: field::ARGUMENT,
                multiple: true,
                required: true,
                kinds: &[kind::ARGUMENT],
            },
        ],
    ),
    (
        kind::ASSIGNMENT,
        &[
            FieldInfo {
                name: field::LEFT,
                multiple: false,
                required: true,
                kinds: &[kind::COMPONENT_ACCESS, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::RIGHT,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::BACKWARD_HANDLER,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
        ],
    ),
    (
        kind::BINARY_EXPRESSION,
        &[
            FieldInfo {
                name: field::LEFT,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::OPERATOR,
                multiple: false,
                required: true,
                kinds: &["*", "+", "-", "/", "<", "<=", "<>", "=", ">", ">=", "and", "div", "mod", "or", "xor"],
            },
            FieldInfo {
                name: field::RIGHT,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::COMPACT_IF_STATEMENT,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: false,
                required: true,
                kinds: &[kind::ASSIGNMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::GOTO_STATEMENT, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TRYNEXT_STATEMENT],
            },
            FieldInfo {
                name: field::CONDITION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::COMPONENT_ACCESS,
        &[
            FieldInfo {
                name: field::COMPONENT,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER],
            },
            FieldInfo {
                name: field::OBJECT,
                multiple: false,
                required: true,
                kinds: &[kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::CONNECT_STATEMENT,
        &[
            FieldInfo {
                name: field::INTERRUPT,
                multiple: false,
                required: true,
                kinds: &[kind::COMPONENT_ACCESS, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::TRAP,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::DATA_DECLARATION,
        &[
            FieldInfo {
                name: field::DIMENSIONS,
                multiple: false,
                required: false,
                kinds: &[kind::DIMENSION_LIST],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
            FieldInfo {
                name: field::STORAGE,
                multiple: false,
                required: true,
                kinds: &["const", "pers", "var"],
            },
            FieldInfo {
                name: field::TYPE,
                multiple: false,
                required: true,
                kinds: &[kind::PLACEHOLDER, kind::TYPE_IDENTIFIER],
            },
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::DEFAULT_CASE,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
        ],
    ),
    (
        kind::DIMENSION_LIST,
        &[
            FieldInfo {
                name: field::DIMENSION,
                multiple: true,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::ELSE_CLAUSE,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
        ],
    ),
    (
        kind::ELSEIF_CLAUSE,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::CONDITION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::ERROR_HANDLER,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::ERROR,
                multiple: true,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::FOR_STATEMENT,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::FROM,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::STEP,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::TO,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::VARIABLE,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::FUNCTION_CALL,
        &[
            FieldInfo {
                name: field::ARGUMENTS,
                multiple: false,
                required: false,
                kinds: &[kind::ARGUMENT_LIST],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER],
            },
        ],
    ),
    (
        kind::FUNCTION_DECLARATION,
        &[
            FieldInfo {
                name: field::BACKWARD,
                multiple: false,
                required: false,
                kinds: &[kind::BACKWARD_HANDLER],
            },
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::DATA_DECLARATION, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::ERROR,
                multiple: false,
                required: false,
                kinds: &[kind::ERROR_HANDLER],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::PARAMETERS,
                multiple: false,
                required: false,
                kinds: &[kind::PARAMETER_LIST],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
            FieldInfo {
                name: field::TYPE,
                multiple: false,
                required: true,
                kinds: &[kind::PLACEHOLDER, kind::TYPE_IDENTIFIER],
            },
            FieldInfo {
                name: field::UNDO,
                multiple: false,
                required: false,
                kinds: &[kind::UNDO_HANDLER],
            },
        ],
    ),
    (
        kind::GOTO_STATEMENT,
        &[
            FieldInfo {
                name: field::LABEL,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::HEADER_ENTRY,
        &[
            FieldInfo {
                name: field::KEY,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER],
            },
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: true,
                kinds: &[kind::HEADER_VALUE],
            },
        ],
    ),
    (
        kind::IF_STATEMENT,
        &[
            FieldInfo {
                name: field::ALTERNATIVE,
                multiple: true,
                required: false,
                kinds: &[kind::ELSE_CLAUSE, kind::ELSEIF_CLAUSE, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::CONDITION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::INDEX_EXPRESSION,
        &[
            FieldInfo {
                name: field::INDEX,
                multiple: true,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::OBJECT,
                multiple: false,
                required: true,
                kinds: &[kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::LABEL,
        &[
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER],
            },
        ],
    ),
    (
        kind::LATE_BINDING,
        &[
            FieldInfo {
                name: field::EXPRESSION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::MODULE,
        &[
            FieldInfo {
                name: field::ATTRIBUTES,
                multiple: false,
                required: false,
                kinds: &[kind::MODULE_ATTRIBUTES],
            },
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ALIAS_DECLARATION, kind::DATA_DECLARATION, kind::FUNCTION_DECLARATION, kind::PLACEHOLDER, kind::PROCEDURE_DECLARATION, kind::RECORD_DECLARATION, kind::TRAP_DECLARATION],
            },
            FieldInfo {
                name: field::HEADER,
                multiple: false,
                required: false,
                kinds: &[kind::MODULE_HEADER],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::MODULE_ATTRIBUTES,
        &[
            FieldInfo {
                name: field::ATTRIBUTE,
                multiple: true,
                required: true,
                kinds: &[kind::MODULE_ATTRIBUTE],
            },
        ],
    ),
    (
        kind::MODULE_HEADER,
        &[
            FieldInfo {
                name: field::ENTRY,
                multiple: true,
                required: false,
                kinds: &[kind::HEADER_ENTRY],
            },
        ],
    ),
    (
        kind::OPTIONAL_PARAMETER,
        &[
            FieldInfo {
                name: field::ALTERNATIVE,
                multiple: true,
                required: true,
                kinds: &[kind::PARAMETER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::PARAMETER,
        &[
            FieldInfo {
                name: field::DIMENSIONS,
                multiple: false,
                required: false,
                kinds: &[kind::PARAMETER_DIMENSIONS],
            },
            FieldInfo {
                name: field::MODE,
                multiple: false,
                required: false,
                kinds: &["inout", "pers", "var"],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::TYPE,
                multiple: false,
                required: true,
                kinds: &[kind::PLACEHOLDER, kind::TYPE_IDENTIFIER],
            },
        ],
    ),
    (
        kind::PARAMETER_DIMENSIONS,
        &[
            FieldInfo {
                name: field::DIMENSION,
                multiple: true,
                required: true,
                kinds: &["*", kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::PARAMETER_LIST,
        &[
            FieldInfo {
                name: field::PARAMETER,
                multiple: true,
                required: true,
                kinds: &[kind::OPTIONAL_PARAMETER, kind::PARAMETER, kind::PLACEHOLDER],
            },
        ],
    ),
    (
        kind::PARENTHESIZED_EXPRESSION,
        &[
            FieldInfo {
                name: field::EXPRESSION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::PROCEDURE_CALL,
        &[
            FieldInfo {
                name: field::ARGUMENTS,
                multiple: false,
                required: false,
                kinds: &[kind::ARGUMENT_LIST],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::LATE_BINDING],
            },
        ],
    ),
    (
        kind::PROCEDURE_DECLARATION,
        &[
            FieldInfo {
                name: field::BACKWARD,
                multiple: false,
                required: false,
                kinds: &[kind::BACKWARD_HANDLER],
            },
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::DATA_DECLARATION, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::ERROR,
                multiple: false,
                required: false,
                kinds: &[kind::ERROR_HANDLER],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::PARAMETERS,
                multiple: false,
                required: false,
                kinds: &[kind::PARAMETER_LIST],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
            FieldInfo {
                name: field::UNDO,
                multiple: false,
                required: false,
                kinds: &[kind::UNDO_HANDLER],
            },
        ],
    ),
    (
        kind::RAISE_STATEMENT,
        &[
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::RECORD_COMPONENT,
        &[
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::TYPE,
                multiple: false,
                required: true,
                kinds: &[kind::PLACEHOLDER, kind::TYPE_IDENTIFIER],
            },
        ],
    ),
    (
        kind::RECORD_DECLARATION,
        &[
            FieldInfo {
                name: field::COMPONENT,
                multiple: true,
                required: false,
                kinds: &[kind::RECORD_COMPONENT],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
        ],
    ),
    (
        kind::RETURN_STATEMENT,
        &[
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: false,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::TEST_CASE,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::VALUE,
                multiple: true,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::TEST_STATEMENT,
        &[
            FieldInfo {
                name: field::CASE,
                multiple: true,
                required: false,
                kinds: &[kind::PLACEHOLDER, kind::TEST_CASE],
            },
            FieldInfo {
                name: field::DEFAULT,
                multiple: false,
                required: false,
                kinds: &[kind::DEFAULT_CASE],
            },
            FieldInfo {
                name: field::VALUE,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
    (
        kind::TRAP_DECLARATION,
        &[
            FieldInfo {
                name: field::BACKWARD,
                multiple: false,
                required: false,
                kinds: &[kind::BACKWARD_HANDLER],
            },
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::DATA_DECLARATION, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::ERROR,
                multiple: false,
                required: false,
                kinds: &[kind::ERROR_HANDLER],
            },
            FieldInfo {
                name: field::NAME,
                multiple: false,
                required: true,
                kinds: &[kind::IDENTIFIER, kind::PLACEHOLDER],
            },
            FieldInfo {
                name: field::SCOPE,
                multiple: false,
                required: false,
                kinds: &["local", "task"],
            },
            FieldInfo {
                name: field::UNDO,
                multiple: false,
                required: false,
                kinds: &[kind::UNDO_HANDLER],
            },
        ],
    ),
    (
        kind::UNARY_EXPRESSION,
        &[
            FieldInfo {
                name: field::OPERAND,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
            FieldInfo {
                name: field::OPERATOR,
                multiple: false,
                required: true,
                kinds: &["+", "-", "not"],
            },
        ],
    ),
    (
        kind::UNDO_HANDLER,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
        ],
    ),
    (
        kind::WHILE_STATEMENT,
        &[
            FieldInfo {
                name: field::BODY,
                multiple: true,
                required: false,
                kinds: &[kind::ASSIGNMENT, kind::COMPACT_IF_STATEMENT, kind::CONNECT_STATEMENT, kind::EXIT_STATEMENT, kind::FOR_STATEMENT, kind::GOTO_STATEMENT, kind::IF_STATEMENT, kind::LABEL, kind::PLACEHOLDER, kind::PROCEDURE_CALL, kind::RAISE_STATEMENT, kind::RETRY_STATEMENT, kind::RETURN_STATEMENT, kind::TEST_STATEMENT, kind::TRYNEXT_STATEMENT, kind::WHILE_STATEMENT],
            },
            FieldInfo {
                name: field::CONDITION,
                multiple: false,
                required: true,
                kinds: &[kind::AGGREGATE, kind::BINARY_EXPRESSION, kind::BOOLEAN, kind::COMPONENT_ACCESS, kind::FUNCTION_CALL, kind::IDENTIFIER, kind::INDEX_EXPRESSION, kind::NUMBER, kind::PARENTHESIZED_EXPRESSION, kind::PLACEHOLDER, kind::STRING, kind::UNARY_EXPRESSION],
            },
        ],
    ),
];

/// The fields of a named node kind (none for kinds without fields and
/// for names that are no kind).
pub fn fields_of(kind: &str) -> &'static [FieldInfo] {
    KIND_FIELDS
        .binary_search_by(|(k, _)| (*k).cmp(kind))
        .map_or(&[], |i| KIND_FIELDS[i].1)
}
