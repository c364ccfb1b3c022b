ERROR 3:13: syntax error, not formatted: missing a name
