// External scanner for the RAPID grammar.
//
// It recognises one token, `trailing_text`: whatever follows the last
// ENDMODULE of a file when it is not another module, a module header
// (`%%%`) or a comment. Real controller files sometimes carry junk there;
// it must not turn into parse errors.

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
  if (lexer->eof(lexer)) {
    return false;
  }
  int32_t c = lexer->lookahead;
  if (c == '!') {
    return false; // a comment: the ordinary lexer takes it
  }
  if (c == '%') {
    unsigned n = 0;
    while (lexer->lookahead == '%' && n < 3) {
      lexer->advance(lexer, false);
      n++;
    }
    if (n == 3) {
      return false; // the header of another module
    }
  } else if (c == 'm' || c == 'M') {
    const char *word = "module";
    unsigned i = 0;
    while (word[i] != 0 && towlower(lexer->lookahead) == (wint_t)word[i]) {
      lexer->advance(lexer, false);
      i++;
    }
    if (word[i] == 0 && !is_ident_char(lexer->lookahead)) {
      return false; // another module
    }
  }
  while (!lexer->eof(lexer)) {
    lexer->advance(lexer, false);
  }
  lexer->mark_end(lexer);
  lexer->result_symbol = TRAILING_TEXT;
  return true;
}
