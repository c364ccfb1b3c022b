/**
 * @file ABB RAPID grammar for tree-sitter
 * @license MIT OR Apache-2.0
 *
 * Keywords are case-insensitive: each one is a per-letter regex aliased to
 * its lowercase spelling, so the tree shows one anonymous node kind
 * (`"module"`, `"endproc"`, ...) whatever the source case.
 */

/// <reference types="tree-sitter-cli/dsl" />
// @ts-check

// RAPID's operator priority, lowest first. NOT shares the lowest level with
// OR and XOR (as in ABB's priority table; real code relies on it:
// `NOT s = "x"` means `NOT (s = "x")`), so its operand extends over AND,
// comparisons and arithmetic. Unary + and - bind tighter than anything.
const PREC = {
  or: 1, // OR XOR, and prefix NOT
  and: 2, // AND
  compare: 3, // = <> < > <= >=
  additive: 4, // binary + -
  multiplicative: 5, // * / DIV MOD
  unary: 6, // unary + -
  postfix: 7, // a.b  a{i}  f(x)
};

/**
 * A case-insensitive regex for a keyword.
 * @param {string} word
 * @returns {RegExp}
 */
function ci(word) {
  return new RegExp(
    word
      .split('')
      .map((c) => (/[a-z]/i.test(c) ? `[${c.toLowerCase()}${c.toUpperCase()}]` : c))
      .join(''),
  );
}

/**
 * A case-insensitive keyword shown as its lowercase spelling.
 * @param {string} word
 */
function kw(word) {
  return alias(ci(word), word.toLowerCase());
}

/** Words the language reserves: never identifiers. */
const RESERVED = [
  'ALIAS', 'AND', 'BACKWARD', 'CASE', 'CONNECT', 'CONST', 'DEFAULT', 'DIV', 'DO',
  'ELSE', 'ELSEIF', 'ENDFOR', 'ENDFUNC', 'ENDIF', 'ENDMODULE', 'ENDPROC',
  'ENDRECORD', 'ENDTEST', 'ENDTRAP', 'ENDWHILE', 'ERROR', 'EXIT', 'FALSE', 'FOR',
  'FROM', 'FUNC', 'GOTO', 'IF', 'INOUT', 'LOCAL', 'MOD', 'MODULE', 'NOSTEPIN',
  'NOT', 'NOVIEW', 'OR', 'PERS', 'PROC', 'RAISE', 'READONLY', 'RECORD', 'RETRY',
  'RETURN', 'STEP', 'SYSMODULE', 'TASK', 'TEST', 'THEN', 'TO', 'TRAP', 'TRUE',
  'TRYNEXT', 'UNDO', 'VAR', 'VIEWONLY', 'WHILE', 'WITH', 'XOR',
];

/**
 * @param {RuleOrLiteral} rule
 * @param {RuleOrLiteral} sep
 */
function sep1(rule, sep) {
  return seq(rule, repeat(seq(sep, rule)));
}

/**
 * `repeat(rule)` with its first `count` items unrolled into nested
 * optionals: a list of up to `count` items then costs no reduction of its
 * own (it is part of the rule that contains it), where `repeat` costs about
 * two per item (it builds a balanced tree of hidden nodes). The visible tree
 * is the same. For the short lists that make up most of real code
 * (aggregates such as robtargets, arguments).
 * @param {RuleOrLiteral} rule
 * @param {number} count
 */
function unrolledRepeat(rule, count) {
  let tail = repeat(rule);
  for (let i = 0; i < count; i++) {
    tail = optional(seq(rule, tail));
  }
  return tail;
}

/**
 * Data declarations and statements, then the handlers, in their order.
 * @param {any} $
 */
function routineBody($) {
  return [
    repeat(field('body', $._routine_item)),
    optional(field('backward', $.backward_handler)),
    optional(field('error', $.error_handler)),
    optional(field('undo', $.undo_handler)),
  ];
}

module.exports = grammar({
  name: 'rapid',

  // `_incomplete`: where a half-typed statement breaks off at the end of a
  // line (after `\`, `:=`, a `,`, inside a string or an aggregate) and
  // the next line starts with a keyword that cannot continue it (`ENDPROC`,
  // `ELSE`, `PROC`...), a zero-width stand-in for what is missing. It ends
  // the broken part, so that error recovery needs one missing `;` and the
  // statement stays inside its routine. Only the scanner makes it, and only
  // there, where the text is certainly wrong; the statement then always
  // lacks its `;` (MISSING in the tree). `_incomplete_string` is the same
  // at the end of a line inside a string (where `!` and blanks are text).
  externals: $ => [$.trailing_text, $._error_sentinel, $._incomplete, $._incomplete_string],

  // Blanks are the ASCII ones (space, tab, line breaks, form feed): a
  // no-break space or an ideographic space is no blank to the controller.
  extras: $ => [/[ \t\n\r\f\v]/, /\uFEFF/, $.comment],

  word: $ => $.identifier,

  reserved: {
    global: _ => RESERVED.map(ci),
  },

  // No `supertypes`: a supertype is a real (hidden) node, one reduction
  // more for every expression, statement and declaration, and nothing
  // queries them. Hidden pass-through rules are inlined for the same reason.
  // The visible tree is the same either way. Not inlined: `_expression`
  // (error recovery would prefer a missing `TRUE` to a missing name),
  // `_type` (tree-sitter drops its alias when inlined), `_target` (recursive).
  inline: $ => [
    $._declaration,
    $._statement,
    $._routine_item,
    $._simple_statement,
    $._primary_expression,
    $._first_parameter,
    $._scope,
    $._name,
  ],

  conflicts: $ => [],

  rules: {
    // text after an ENDMODULE that is not a module is `trailing_text`
    source_file: $ => optional(seq(
      $.module,
      repeat(choice($.module, $.trailing_text)),
    )),

    // ------------------------------------------------------------------
    // Modules

    module: $ => seq(
      optional(field('header', $.module_header)),
      kw('MODULE'),
      field('name', $._name),
      optional(field('attributes', $.module_attributes)),
      repeat(field('body', $._declaration)),
      kw('ENDMODULE'),
    ),

    // %%%  VERSION:1  LANGUAGE:ENGLISH  %%%
    module_header: $ => seq(
      '%%%',
      repeat(field('entry', $.header_entry)),
      '%%%',
    ),

    header_entry: $ => seq(
      field('key', $.identifier),
      ':',
      field('value', $.header_value),
    ),

    // `1`, `1.0.3`, `ENGLISH`: whatever stands after the colon
    header_value: _ => /[^\s%!]+/,

    module_attributes: $ => seq(
      '(',
      sep1(field('attribute', $.module_attribute), ','),
      ')',
    ),

    module_attribute: _ => choice(
      kw('SYSMODULE'),
      kw('NOVIEW'),
      kw('NOSTEPIN'),
      kw('VIEWONLY'),
      kw('READONLY'),
    ),

    // ------------------------------------------------------------------
    // Declarations

    _declaration: $ => choice(
      $.data_declaration,
      $.record_declaration,
      $.alias_declaration,
      $.procedure_declaration,
      $.function_declaration,
      $.trap_declaration,
      $.placeholder,
    ),

    _scope: _ => choice(kw('LOCAL'), kw('TASK')),

    data_declaration: $ => seq(
      optional(field('scope', $._scope)),
      field('storage', choice(kw('VAR'), kw('PERS'), kw('CONST'))),
      field('type', $._type),
      field('name', $._name),
      optional(field('dimensions', $.dimension_list)),
      optional(seq(':=', field('value', $._expression))),
      ';',
    ),

    dimension_list: $ => seq(
      '{',
      sep1(field('dimension', $._expression), ','),
      '}',
    ),

    record_declaration: $ => seq(
      optional(field('scope', $._scope)),
      kw('RECORD'),
      field('name', $._name),
      repeat(field('component', $.record_component)),
      kw('ENDRECORD'),
    ),

    record_component: $ => seq(
      field('type', $._type),
      field('name', $._name),
      ';',
    ),

    alias_declaration: $ => seq(
      optional(field('scope', $._scope)),
      kw('ALIAS'),
      field('type', $._type),
      field('name', $._name),
      ';',
    ),

    procedure_declaration: $ => seq(
      optional(field('scope', $._scope)),
      kw('PROC'),
      field('name', $._name),
      '(',
      optional(field('parameters', $.parameter_list)),
      ')',
      ...routineBody($),
      kw('ENDPROC'),
    ),

    function_declaration: $ => seq(
      optional(field('scope', $._scope)),
      kw('FUNC'),
      field('type', $._type),
      field('name', $._name),
      '(',
      optional(field('parameters', $.parameter_list)),
      ')',
      ...routineBody($),
      kw('ENDFUNC'),
    ),

    trap_declaration: $ => seq(
      optional(field('scope', $._scope)),
      kw('TRAP'),
      field('name', $._name),
      ...routineBody($),
      kw('ENDTRAP'),
    ),

    _routine_item: $ => choice($.data_declaration, $._statement),

    backward_handler: $ => seq(
      kw('BACKWARD'),
      repeat(field('body', $._statement)),
    ),

    error_handler: $ => seq(
      kw('ERROR'),
      optional(seq(
        '(',
        sep1(field('error', $._expression), ','),
        ')',
      )),
      repeat(field('body', $._statement)),
    ),

    undo_handler: $ => seq(
      kw('UNDO'),
      repeat(field('body', $._statement)),
    ),

    // first parameter, then `, parameter` or `\optional` (comma optional)
    parameter_list: $ => seq(
      $._first_parameter,
      repeat(choice(
        seq(',', $._first_parameter),
        field('parameter', $.optional_parameter),
      )),
    ),

    _first_parameter: $ => field('parameter', choice(
      $.parameter,
      $.optional_parameter,
      $.placeholder,
    )),

    parameter: $ => seq(
      optional(field('mode', choice(kw('VAR'), kw('PERS'), kw('INOUT')))),
      field('type', $._type),
      field('name', $._name),
      optional(field('dimensions', $.parameter_dimensions)),
    ),

    // \num a | switch b
    optional_parameter: $ => seq(
      '\\',
      sep1(field('alternative', choice($.parameter, $.placeholder)), '|'),
    ),

    // {*} {*,*}
    parameter_dimensions: $ => seq(
      '{',
      sep1(field('dimension', choice('*', $.placeholder)), ','),
      '}',
    ),

    // ------------------------------------------------------------------
    // Statements

    _statement: $ => choice(
      $.assignment,
      $.procedure_call,
      $.if_statement,
      $.compact_if_statement,
      $.for_statement,
      $.while_statement,
      $.test_statement,
      $.label,
      $.goto_statement,
      $.return_statement,
      $.raise_statement,
      $.exit_statement,
      $.retry_statement,
      $.trynext_statement,
      $.connect_statement,
      $.placeholder,
    ),

    assignment: $ => seq(
      field('left', $._target),
      ':=',
      choice(field('right', $._expression), $._incomplete),
      ';',
    ),

    procedure_call: $ => seq(
      field('name', choice($.identifier, $.late_binding)),
      optional(field('arguments', $.argument_list)),
      ';',
    ),

    // %"name"% or %expr%
    late_binding: $ => seq('%', field('expression', $._expression), '%'),

    if_statement: $ => seq(
      kw('IF'),
      field('condition', $._expression),
      kw('THEN'),
      repeat(field('body', $._statement)),
      repeat(field('alternative', choice($.elseif_clause, alias($._elseif_placeholder, $.placeholder)))),
      optional(field('alternative', $.else_clause)),
      kw('ENDIF'),
    ),

    elseif_clause: $ => seq(
      kw('ELSEIF'),
      field('condition', $._expression),
      kw('THEN'),
      repeat(field('body', $._statement)),
    ),

    else_clause: $ => seq(
      kw('ELSE'),
      repeat(field('body', $._statement)),
    ),

    // IF cond stmt
    compact_if_statement: $ => seq(
      kw('IF'),
      field('condition', $._expression),
      field('body', $._simple_statement),
    ),

    _simple_statement: $ => choice(
      $.assignment,
      $.procedure_call,
      $.goto_statement,
      $.return_statement,
      $.raise_statement,
      $.exit_statement,
      $.retry_statement,
      $.trynext_statement,
      $.connect_statement,
      $.placeholder,
    ),

    for_statement: $ => seq(
      kw('FOR'),
      field('variable', $._name),
      kw('FROM'),
      field('from', $._expression),
      kw('TO'),
      field('to', $._expression),
      optional(seq(kw('STEP'), field('step', $._expression))),
      kw('DO'),
      repeat(field('body', $._statement)),
      kw('ENDFOR'),
    ),

    while_statement: $ => seq(
      kw('WHILE'),
      field('condition', $._expression),
      kw('DO'),
      repeat(field('body', $._statement)),
      kw('ENDWHILE'),
    ),

    test_statement: $ => seq(
      kw('TEST'),
      field('value', $._expression),
      repeat(field('case', choice($.test_case, alias($._case_placeholder, $.placeholder)))),
      optional(field('default', $.default_case)),
      kw('ENDTEST'),
    ),

    test_case: $ => seq(
      kw('CASE'),
      sep1(field('value', $._expression), ','),
      ':',
      repeat(field('body', $._statement)),
    ),

    default_case: $ => seq(
      kw('DEFAULT'),
      ':',
      repeat(field('body', $._statement)),
    ),

    label: $ => seq(field('name', $.identifier), ':'),

    goto_statement: $ => seq(kw('GOTO'), field('label', $._name), ';'),

    return_statement: $ => seq(kw('RETURN'), optional(field('value', $._expression)), ';'),

    raise_statement: $ => seq(kw('RAISE'), optional(field('value', $._expression)), ';'),

    exit_statement: _ => seq(kw('EXIT'), ';'),

    retry_statement: _ => seq(kw('RETRY'), ';'),

    trynext_statement: _ => seq(kw('TRYNEXT'), ';'),

    connect_statement: $ => seq(
      kw('CONNECT'),
      field('interrupt', $._target),
      kw('WITH'),
      field('trap', $._name),
      ';',
    ),

    // ------------------------------------------------------------------
    // Arguments

    // first argument, then `, argument` or `\optional` (comma optional)
    argument_list: $ => seq(
      field('argument', alias($._first_argument, $.argument)),
      unrolledRepeat(choice(
        seq(',', field('argument', $.argument)),
        field('argument', alias($._optional_argument, $.argument)),
      ), 5),
    ),

    // after a comma, the rest of a broken line may be missing
    argument: $ => choice($._first_argument, $._incomplete),

    _first_argument: $ => choice(
      field('value', choice($._expression, $.star)),
      seq(
        field('name', $.identifier),
        ':=',
        choice(field('value', choice($._expression, $.star)), $._incomplete),
      ),
      $._optional_argument,
    ),

    // \Switch  \Opt:=value  \Opt?variable
    _optional_argument: $ => seq(
      '\\',
      choice(
        seq(
          field('name', $._name),
          optional(choice(
            seq(':=', choice(field('value', choice($._expression, $.star)), $._incomplete)),
            seq('?', field('conditional', $._expression)),
          )),
        ),
        $._incomplete,
      ),
    ),

    // `*` in an argument: the target stored in the instruction
    star: _ => '*',

    // ------------------------------------------------------------------
    // Expressions

    _expression: $ => choice(
      $.binary_expression,
      $.unary_expression,
      $._primary_expression,
      $.aggregate,
      $.number,
      $.string,
      $.boolean,
    ),

    // what `.component` and `{index}` can follow
    _primary_expression: $ => choice(
      $.parenthesized_expression,
      $.function_call,
      $.component_access,
      $.index_expression,
      $.identifier,
      $.placeholder,
    ),

    // assignable places: the same node kinds, without calls or parentheses
    _target: $ => choice(
      $.identifier,
      alias($._target_component_access, $.component_access),
      alias($._target_index_expression, $.index_expression),
      $.placeholder,
    ),

    _target_component_access: $ => prec(PREC.postfix, seq(
      field('object', $._target),
      '.',
      field('component', $.identifier),
    )),

    _target_index_expression: $ => prec(PREC.postfix, seq(
      field('object', $._target),
      '{',
      sep1(field('index', $._expression), ','),
      '}',
    )),

    binary_expression: $ => {
      /** @type {[number, RuleOrLiteral][]} */
      const table = [
        [PREC.or, choice(kw('OR'), kw('XOR'))],
        [PREC.and, kw('AND')],
        [PREC.compare, choice('=', '<>', '<', '>', '<=', '>=')],
        [PREC.additive, choice('+', '-')],
        [PREC.multiplicative, choice('*', '/', kw('DIV'), kw('MOD'))],
      ];
      return choice(...table.map(([p, op]) => prec.left(p, seq(
        field('left', $._expression),
        field('operator', op),
        field('right', $._expression),
      ))));
    },

    unary_expression: $ => choice(
      prec(PREC.unary, seq(
        field('operator', choice('+', '-')),
        field('operand', $._expression),
      )),
      prec.left(PREC.or, seq(
        field('operator', kw('NOT')),
        field('operand', $._expression),
      )),
    ),

    parenthesized_expression: $ => seq('(', field('expression', $._expression), ')'),

    function_call: $ => prec(PREC.postfix, seq(
      field('name', $.identifier),
      '(',
      optional(field('arguments', $.argument_list)),
      ')',
    )),

    aggregate: $ => seq(
      '[',
      field('element', $._expression),
      unrolledRepeat(seq(',', field('element', $._expression)), 7),
      choice(']', seq(optional(','), $._incomplete)),
    ),

    component_access: $ => prec(PREC.postfix, seq(
      field('object', $._primary_expression),
      '.',
      field('component', $.identifier),
    )),

    index_expression: $ => prec(PREC.postfix, seq(
      field('object', $._primary_expression),
      '{',
      sep1(field('index', $._expression), ','),
      '}',
    )),

    boolean: _ => choice(kw('TRUE'), kw('FALSE')),

    // ------------------------------------------------------------------
    // Tokens

    _type: $ => choice(alias($.identifier, $.type_identifier), $.placeholder),

    _name: $ => choice($.identifier, $.placeholder),

    // A letter of ISO 8859-1 (the controller's character set: A-Z, a-z,
    // À-Ö, Ø-ö, ø-ÿ), then letters, digits and `_`.
    identifier: _ => /[A-Za-z\u00C0-\u00D6\u00D8-\u00F6\u00F8-\u00FF][A-Za-z0-9_\u00C0-\u00D6\u00D8-\u00F6\u00F8-\u00FF]*/,

    // FlexPendant placeholders: <SMT> <EXP> <ARG> <VAR> <ID> <DDN> ...
    placeholder: _ => token(prec(1, /<[A-Z]{2,4}>/)),

    // where a CASE or ELSEIF clause can stand, these two are clauses, not
    // statements of the clause before
    _case_placeholder: _ => token(prec(2, '<CSE>')),
    _elseif_placeholder: _ => token(prec(2, '<EIT>')),

    number: _ => token(choice(
      /0[xX][0-9A-Fa-f]+/,
      /0[oO][0-7]+/,
      /0[bB][01]+/,
      /(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?/,
    )),

    string: $ => seq(
      '"',
      repeat(choice($.string_content, $.escape_sequence)),
      choice(token.immediate('"'), $._incomplete_string),
    ),

    string_content: _ => token.immediate(prec(1, choice(/[^"\\\r\n]+/, '\\'))),

    escape_sequence: _ => token.immediate(prec(1, choice('""', '\\\\', /\\[0-9A-Fa-f]{2}/))),

    comment: _ => token(seq('!', /[^\r\n]*/)),
  },
});
