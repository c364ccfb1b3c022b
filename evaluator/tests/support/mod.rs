//! Test support: a tiny recursive-descent reader for RAPID expressions and
//! declarations, so fixtures can be written in RAPID. Not part of the crate:
//! the real lowering is the analyzer's, from the tree-sitter tree.
#![allow(dead_code)]

use rapid_evaluator::{Arg, BinOp, Expr, MapEnv, Type, UnOp, VarKind};

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(String),
    Str(String),
    Ident(String),
    Op(String),
}

fn lex(src: &str) -> Result<Vec<Tok>, String> {
    let cs: Vec<char> = src.chars().collect();
    let mut i = 0;
    let mut out = Vec::new();
    while i < cs.len() {
        let c = cs[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit()
            || (c == '.' && cs.get(i + 1).is_some_and(|d| d.is_ascii_digit()))
        {
            let s = i;
            if c == '0' && matches!(cs.get(i + 1), Some('x' | 'X' | 'o' | 'O' | 'b' | 'B')) {
                i += 2;
                while i < cs.len() && cs[i].is_ascii_alphanumeric() {
                    i += 1;
                }
            } else {
                while i < cs.len() && (cs[i].is_ascii_digit() || cs[i] == '.') {
                    i += 1;
                }
                if i < cs.len() && (cs[i] == 'e' || cs[i] == 'E') {
                    i += 1;
                    if i < cs.len() && (cs[i] == '+' || cs[i] == '-') {
                        i += 1;
                    }
                    while i < cs.len() && cs[i].is_ascii_digit() {
                        i += 1;
                    }
                }
            }
            out.push(Tok::Num(cs[s..i].iter().collect()));
        } else if c == '"' {
            let s = i;
            i += 1;
            loop {
                match cs.get(i) {
                    None => return Err("unterminated string".into()),
                    Some('"') if cs.get(i + 1) == Some(&'"') => i += 2,
                    Some('"') => {
                        i += 1;
                        break;
                    }
                    _ => i += 1,
                }
            }
            out.push(Tok::Str(cs[s..i].iter().collect()));
        } else if c.is_alphabetic() || c == '_' {
            let s = i;
            while i < cs.len() && (cs[i].is_alphanumeric() || cs[i] == '_') {
                i += 1;
            }
            out.push(Tok::Ident(cs[s..i].iter().collect()));
        } else {
            let two: String = cs[i..(i + 2).min(cs.len())].iter().collect();
            if [":=", "<=", ">=", "<>"].contains(&two.as_str()) {
                out.push(Tok::Op(two));
                i += 2;
            } else {
                out.push(Tok::Op(c.to_string()));
                i += 1;
            }
        }
    }
    Ok(out)
}

struct P {
    t: Vec<Tok>,
    i: usize,
}

fn kw(t: Option<&Tok>, k: &str) -> bool {
    matches!(t, Some(Tok::Ident(s)) if s.eq_ignore_ascii_case(k))
}

impl P {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }
    fn op(&self, o: &str) -> bool {
        matches!(self.peek(), Some(Tok::Op(s)) if s == o)
    }
    fn eat(&mut self, o: &str) -> bool {
        if self.op(o) {
            self.i += 1;
            true
        } else {
            false
        }
    }
    fn expect(&mut self, o: &str) -> Result<(), String> {
        if self.eat(o) {
            Ok(())
        } else {
            Err(format!("expected `{o}` at token {}", self.i))
        }
    }
    fn ident(&mut self) -> Result<String, String> {
        match self.peek().cloned() {
            Some(Tok::Ident(s)) => {
                self.i += 1;
                Ok(s)
            }
            t => Err(format!("expected a name, found {t:?}")),
        }
    }
    fn expr(&mut self) -> Result<Expr, String> {
        let mut l = self.conj()?;
        loop {
            let op = if kw(self.peek(), "OR") {
                BinOp::Or
            } else if kw(self.peek(), "XOR") {
                BinOp::Xor
            } else {
                return Ok(l);
            };
            self.i += 1;
            let r = self.conj()?;
            l = Expr::Binary(op, Box::new(l), Box::new(r));
        }
    }
    fn conj(&mut self) -> Result<Expr, String> {
        let mut l = self.not()?;
        while kw(self.peek(), "AND") {
            self.i += 1;
            let r = self.not()?;
            l = Expr::Binary(BinOp::And, Box::new(l), Box::new(r));
        }
        Ok(l)
    }
    fn not(&mut self) -> Result<Expr, String> {
        if kw(self.peek(), "NOT") {
            self.i += 1;
            return Ok(Expr::Unary(UnOp::Not, Box::new(self.not()?)));
        }
        self.cmp()
    }
    fn cmp(&mut self) -> Result<Expr, String> {
        let l = self.add()?;
        let ops = [
            ("=", BinOp::Eq),
            ("<>", BinOp::Ne),
            ("<", BinOp::Lt),
            ("<=", BinOp::Le),
            (">", BinOp::Gt),
            (">=", BinOp::Ge),
        ];
        for (s, op) in ops {
            if self.eat(s) {
                let r = self.add()?;
                return Ok(Expr::Binary(op, Box::new(l), Box::new(r)));
            }
        }
        Ok(l)
    }
    fn add(&mut self) -> Result<Expr, String> {
        let mut l = self.mul()?;
        loop {
            let op = if self.eat("+") {
                BinOp::Add
            } else if self.eat("-") {
                BinOp::Sub
            } else {
                return Ok(l);
            };
            let r = self.mul()?;
            l = Expr::Binary(op, Box::new(l), Box::new(r));
        }
    }
    fn mul(&mut self) -> Result<Expr, String> {
        let mut l = self.unary()?;
        loop {
            let op = if self.eat("*") {
                BinOp::Mul
            } else if self.eat("/") {
                BinOp::Div
            } else if kw(self.peek(), "DIV") {
                self.i += 1;
                BinOp::IntDiv
            } else if kw(self.peek(), "MOD") {
                self.i += 1;
                BinOp::Mod
            } else {
                return Ok(l);
            };
            let r = self.unary()?;
            l = Expr::Binary(op, Box::new(l), Box::new(r));
        }
    }
    fn unary(&mut self) -> Result<Expr, String> {
        if self.eat("-") {
            return Ok(Expr::Unary(UnOp::Neg, Box::new(self.unary()?)));
        }
        if self.eat("+") {
            return Ok(Expr::Unary(UnOp::Plus, Box::new(self.unary()?)));
        }
        self.postfix()
    }
    fn postfix(&mut self) -> Result<Expr, String> {
        let mut e = self.primary()?;
        loop {
            if self.eat(".") {
                e = Expr::Component(Box::new(e), self.ident()?);
            } else if self.eat("{") {
                let mut ix = vec![self.expr()?];
                while self.eat(",") {
                    ix.push(self.expr()?);
                }
                self.expect("}")?;
                e = Expr::Index(Box::new(e), ix);
            } else {
                return Ok(e);
            }
        }
    }
    fn primary(&mut self) -> Result<Expr, String> {
        match self.peek().cloned() {
            Some(Tok::Num(n)) => {
                self.i += 1;
                Ok(Expr::Num(n))
            }
            Some(Tok::Str(s)) => {
                self.i += 1;
                Ok(Expr::Str(s))
            }
            Some(Tok::Ident(s)) => {
                self.i += 1;
                if s.eq_ignore_ascii_case("TRUE") {
                    return Ok(Expr::Bool(true));
                }
                if s.eq_ignore_ascii_case("FALSE") {
                    return Ok(Expr::Bool(false));
                }
                if s == "UNKNOWN_EXPR" {
                    return Ok(Expr::Unknown);
                }
                if self.eat("(") {
                    let mut args = Vec::new();
                    if !self.eat(")") {
                        loop {
                            args.push(self.arg()?);
                            if self.eat(")") {
                                break;
                            }
                            if !self.eat(",") && !self.op("\\") {
                                return Err("expected `,` or `)` in arguments".into());
                            }
                        }
                    }
                    return Ok(Expr::Call { name: s, args });
                }
                Ok(Expr::Name(s))
            }
            Some(Tok::Op(o)) if o == "(" => {
                self.i += 1;
                let e = self.expr()?;
                self.expect(")")?;
                Ok(e)
            }
            Some(Tok::Op(o)) if o == "[" => {
                self.i += 1;
                let mut items = vec![self.expr()?];
                while self.eat(",") {
                    items.push(self.expr()?);
                }
                self.expect("]")?;
                Ok(Expr::Aggregate(items))
            }
            t => Err(format!("unexpected {t:?}")),
        }
    }
    fn arg(&mut self) -> Result<Arg, String> {
        if self.eat("\\") {
            let name = self.ident()?;
            if self.eat(":=") {
                return Ok(Arg::named(name, self.expr()?));
            }
            return Ok(Arg::switch(name));
        }
        if let (Some(Tok::Ident(n)), Some(Tok::Op(o))) =
            (self.t.get(self.i), self.t.get(self.i + 1))
            && o == ":="
        {
            let n = n.clone();
            self.i += 2;
            return Ok(Arg::named(n, self.expr()?));
        }
        Ok(Arg::positional(self.expr()?))
    }
    fn ty(&mut self) -> Result<Type, String> {
        let name = self.ident()?;
        self.ty_dims(name)
    }
    fn ty_dims(&mut self, name: String) -> Result<Type, String> {
        let mut dims = Vec::new();
        if self.eat("{") {
            loop {
                match self.peek().cloned() {
                    Some(Tok::Num(n)) => {
                        self.i += 1;
                        dims.push(n.parse::<usize>().map_err(|e| e.to_string())?);
                    }
                    t => return Err(format!("expected a dimension, found {t:?}")),
                }
                if !self.eat(",") {
                    break;
                }
            }
            self.expect("}")?;
        }
        Ok(Type { name, dims })
    }
}

/// Reads one RAPID expression.
pub fn parse_expr(src: &str) -> Result<Expr, String> {
    let mut p = P { t: lex(src)?, i: 0 };
    let e = p.expr()?;
    if p.i != p.t.len() {
        return Err(format!("trailing input in `{src}`"));
    }
    Ok(e)
}

/// Reads a type such as `num` or `robtarget{3}`.
pub fn parse_type(src: &str) -> Result<Type, String> {
    let mut p = P { t: lex(src)?, i: 0 };
    let t = p.ty()?;
    if p.i != p.t.len() {
        return Err(format!("trailing input in type `{src}`"));
    }
    Ok(t)
}

/// Adds one declaration to `env`:
/// `CONST|VAR|PERS type name [:= expr];` or
/// `RECORD name type field; type field; ...` or `ALIAS type name;`.
pub fn declare(env: &mut MapEnv, src: &str) -> Result<(), String> {
    let mut p = P {
        t: lex(src.trim().trim_end_matches(';'))?,
        i: 0,
    };
    let kind = p.ident()?;
    match kind.to_ascii_uppercase().as_str() {
        "RECORD" => {
            let name = p.ident()?;
            let mut fields = Vec::new();
            while p.peek().is_some() {
                let t = p.ty()?;
                let f = p.ident()?;
                fields.push((f, t));
                p.eat(";");
            }
            env.record(&name, fields);
        }
        "ALIAS" => {
            let t = p.ty()?;
            let name = p.ident()?;
            env.alias(&name, t);
        }
        k @ ("CONST" | "VAR" | "PERS") => {
            // RAPID writes the dimensions after the name: `CONST num a{3} := ...`
            let tyname = p.ident()?;
            let name = p.ident()?;
            let mut ty = p.ty_dims(tyname)?;
            if ty.dims.is_empty() {
                ty = Type::named(ty.name);
            }
            let init = if p.eat(":=") { Some(p.expr()?) } else { None };
            if p.i != p.t.len() {
                return Err(format!("trailing input in `{src}`"));
            }
            match k {
                "CONST" => {
                    let init = init.ok_or("a CONST needs a value")?;
                    env.constant(&name, ty, init);
                }
                "VAR" => {
                    env.variable(&name, VarKind::Var, ty, init);
                }
                _ => {
                    env.variable(&name, VarKind::Pers, ty, init);
                }
            }
        }
        other => return Err(format!("unknown declaration `{other}`")),
    }
    Ok(())
}
