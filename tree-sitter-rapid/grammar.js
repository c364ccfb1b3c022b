/**
 * @file ABB RAPID grammar for tree-sitter (placeholder, being written)
 */
module.exports = grammar({
  name: 'rapid',
  extras: $ => [/\s/, $.comment],
  word: $ => $.identifier,
  rules: {
    source_file: $ => repeat($.module),
    module: $ => seq(/[mM][oO][dD][uU][lL][eE]/, field('name', $.identifier), /[eE][nN][dD][mM][oO][dD][uU][lL][eE]/),
    identifier: _ => /[A-Za-z][A-Za-z0-9_]*/,
    comment: _ => token(seq('!', /.*/)),
  },
});
