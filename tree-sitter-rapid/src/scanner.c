// External scanner for the RAPID grammar.
//
// It recognises one token, `trailing_text`: text after an ENDMODULE that
// is not a comment, up to the end of the file or to the next line that
// starts a module (`MODULE` or a `%%%` header). Real controller files
// sometimes carry junk there; it must not turn into parse errors.

#include "tree_sitter/parser.h"

#include <wctype.h>

enum TokenType {
  TRAILING_TEXT,
  ERROR_SENTINEL,
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

static bool is_ident_char(int32_t c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         c == '_';
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

bool tree_sitter_rapid_external_scanner_scan(void *payload, TSLexer *lexer,
                                             const bool *valid_symbols) {
  (void)payload;
  // During error recovery every symbol is valid: never claim text then.
  if (valid_symbols[ERROR_SENTINEL] || !valid_symbols[TRAILING_TEXT]) {
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
