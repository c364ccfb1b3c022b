// External scanner for the RAPID grammar.
//
// It recognises these tokens:
// - `trailing_text`: text after an ENDMODULE that is not a comment, up to
//   the end of the file or to the next line that starts a module (`MODULE`
//   or a `%%%` header). Real controller files sometimes carry junk there;
//   it must not turn into parse errors.
// - `_incomplete` (and `_incomplete_string`, inside a string): zero-width,
//   where a half-typed statement breaks off at the end of a line and the
//   next line (past blank and comment lines) starts with a keyword that
//   cannot continue it, or the file ends. The
//   grammar takes it only where something is certainly missing (after
//   `\`, `:=`, `,`, inside a string or an aggregate), so the text is wrong
//   whenever it is made; it lets error recovery end the statement there
//   instead of reading the next routine as its continuation.

#include "tree_sitter/parser.h"

#include <string.h>
#include <wctype.h>

enum TokenType {
  TRAILING_TEXT,
  ERROR_SENTINEL,
  INCOMPLETE,
  INCOMPLETE_STRING,
};

void *tree_sitter_rapid_external_scanner_create(void) { return NULL; }

void tree_sitter_rapid_external_scanner_destroy(void *payload) { (void)payload; }

unsigned tree_sitter_rapid_external_scanner_serialize(void *payload, char *buffer) {
  (void)payload;
  (void)buffer;
  return 0;
}

void tree_sitter_rapid_external_scanner_deserialize(void *payload, const char *buffer,
                                                    unsigned length) {
  (void)payload;
  (void)buffer;
  (void)length;
}

// A letter of ISO 8859-1 (as the grammar's identifier: A-Z, a-z, À-Ö,
// Ø-ö, ø-ÿ), a digit or `_`.
static bool is_ident_char(int32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         c == '_' || (c >= 0xC0 && c <= 0xFF && c != 0xD7 && c != 0xF7);
}

static bool is_newline(int32_t c) { return c == '\n' || c == '\r'; }

static void skip_blanks(TSLexer *lexer) {
  while (lexer->lookahead == ' ' || lexer->lookahead == '\t') {
    lexer->advance(lexer, false);
  }
}

// Consumes what looks like the start of a module: a `%%%` header, or a
// line `MODULE name` followed by nothing but attributes or a comment.
// Returns true when it is one; what was consumed otherwise is ordinary
// text (prose such as "Module written by ..." is not a module).
static bool starts_module(TSLexer *lexer) {
  if (lexer->lookahead == '%') {
    unsigned n = 0;
    while (lexer->lookahead == '%' && n < 3) {
      lexer->advance(lexer, false);
      n++;
    }
    return n == 3;
  }
  const char *word = "module";
  unsigned i = 0;
  while (word[i] != 0 && !lexer->eof(lexer) && towlower(lexer->lookahead) == (wint_t)word[i]) {
    lexer->advance(lexer, false);
    i++;
  }
  if (i == 0 || word[i] != 0 || (lexer->lookahead != ' ' && lexer->lookahead != '\t')) {
    return false;
  }
  skip_blanks(lexer);
  if (lexer->lookahead == '<') {
    lexer->advance(lexer, false); // a placeholder name such as <ID>
  }
  unsigned name = 0;
  while (is_ident_char(lexer->lookahead) || lexer->lookahead == '>') {
    lexer->advance(lexer, false);
    name++;
  }
  if (name == 0) {
    return false;
  }
  skip_blanks(lexer);
  int32_t c = lexer->lookahead;
  return lexer->eof(lexer) || is_newline(c) || c == '(' || c == '!';
}

// Keywords that start a line no statement can continue on: the ends and
// clauses of blocks, routines and modules, declarations and statements
// (not the operators, `TRUE`/`FALSE`, nor `THEN`, `DO`, `TO`, `FROM`,
// `STEP`, `WITH`, which continue the line before).
static const char *const LINE_KEYWORDS[] = {
    "alias",   "backward", "case",    "connect", "const",    "default", "else",
    "elseif",  "endfor",   "endfunc", "endif",   "endmodule", "endproc", "endrecord",
    "endtest", "endtrap",  "endwhile", "error",  "exit",     "for",     "func",
    "goto",    "if",       "local",   "module",  "pers",     "proc",    "raise",
    "record",  "retry",    "return",  "task",    "test",     "trap",    "trynext",
    "undo",    "var",      "while",
};

static void skip_line(TSLexer *lexer) {
  while (!lexer->eof(lexer) && !is_newline(lexer->lookahead)) {
    lexer->advance(lexer, false);
  }
}

// From the current position: the rest of the line is blank (or a
// comment; inside a string, where blanks and `!` are text, the line ends
// right here), and the next line that is not blank or a comment starts
// with one of LINE_KEYWORDS, or the file ends.
static bool line_breaks_off(TSLexer *lexer, bool in_string) {
  if (!in_string) {
    skip_blanks(lexer);
    if (lexer->lookahead == '!') {
      skip_line(lexer);
    }
  }
  if (lexer->eof(lexer)) {
    return true;
  }
  if (!is_newline(lexer->lookahead)) {
    return false;
  }
  for (;;) {
    while (is_newline(lexer->lookahead) || lexer->lookahead == ' ' ||
           lexer->lookahead == '\t' || lexer->lookahead == 0xFEFF) {
      lexer->advance(lexer, false);
    }
    if (lexer->eof(lexer)) {
      return true;
    }
    if (lexer->lookahead != '!') {
      break;
    }
    skip_line(lexer);
  }
  char word[12];
  unsigned n = 0;
  while (is_ident_char(lexer->lookahead)) {
    if (n == sizeof(word) - 1) {
      return false; // longer than every keyword
    }
    word[n++] = (char)towlower(lexer->lookahead);
    lexer->advance(lexer, false);
  }
  word[n] = 0;
  if (n == 0) {
    return false;
  }
  for (unsigned i = 0; i < sizeof(LINE_KEYWORDS) / sizeof(LINE_KEYWORDS[0]); i++) {
    if (strcmp(word, LINE_KEYWORDS[i]) == 0) {
      return true;
    }
  }
  return false;
}

bool tree_sitter_rapid_external_scanner_scan(void *payload, TSLexer *lexer,
                                             const bool *valid_symbols) {
  (void)payload;
  // During error recovery every symbol is valid: never claim text then.
  if (valid_symbols[ERROR_SENTINEL]) {
    return false;
  }
  if (valid_symbols[INCOMPLETE] || valid_symbols[INCOMPLETE_STRING]) {
    bool in_string = valid_symbols[INCOMPLETE_STRING];
    lexer->mark_end(lexer); // zero-width: what follows is only looked at
    if (line_breaks_off(lexer, in_string)) {
      lexer->result_symbol = in_string ? INCOMPLETE_STRING : INCOMPLETE;
      return true;
    }
    return false;
  }
  if (!valid_symbols[TRAILING_TEXT]) {
    return false;
  }
  while (iswspace(lexer->lookahead) || lexer->lookahead == 0xFEFF) {
    lexer->advance(lexer, true);
  }
  if (lexer->eof(lexer) || lexer->lookahead == '!') {
    return false; // the end, or a comment the ordinary lexer takes
  }
  if (starts_module(lexer)) {
    return false; // another module
  }
  // Text up to the end of the file or to a line that starts a module.
  for (;;) {
    while (!lexer->eof(lexer) && !is_newline(lexer->lookahead)) {
      lexer->advance(lexer, false);
    }
    lexer->mark_end(lexer);
    if (lexer->eof(lexer)) {
      break;
    }
    while (is_newline(lexer->lookahead)) {
      lexer->advance(lexer, false);
    }
    skip_blanks(lexer);
    if (lexer->eof(lexer) || starts_module(lexer)) {
      break;
    }
  }
  lexer->result_symbol = TRAILING_TEXT;
  return true;
}
