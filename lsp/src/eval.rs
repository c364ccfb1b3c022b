//! `rapid eval`: compute a RAPID expression the way the controller would,
//! alone or with the data of a program.
//!
//! The expression is parsed with the RAPID grammar inside a small synthetic
//! module, lowered, and evaluated by `rapid_evaluator` through
//! `rapid_analyzer::consteval`. Exit codes: 0 with a value, 1 when the
//! evaluation fails (a run-time error, data that is not constant, an unknown
//! name), 2 for usage errors and expressions that do not parse.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use rapid_analyzer::consteval::{self, EnvOptions};
use rapid_analyzer::lower::{is_expression, lower_with};
use rapid_analyzer::task::{Task, Unit};
use rapid_evaluator::{EvalError, Evaluation};

/// Output formats of `rapid eval`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// The value as RAPID writes it (`ValToStr`).
    Human,
    /// `{"type": ..., "value": ...}`, or `{"error": {"code": ..., "message": ...}}`.
    Json,
}

#[derive(Debug, clap::Args)]
pub struct EvalArgs {
    /// The expression, in RAPID syntax: `'Sqrt(2) * Sin(30)'`.
    #[arg(allow_hyphen_values = true)]
    pub expr: String,
    /// Evaluate with the data of a program: a module (names resolve as in
    /// that module, with the rest of its task) or a folder (the task's
    /// global data).
    #[arg(long, value_name = "PATH")]
    pub file: Option<PathBuf>,
    /// Use the initial values of VAR and PERS data instead of reporting
    /// them as not constant; the result is labelled.
    #[arg(long)]
    pub initial: bool,
    /// How to print the result.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
}

/// The synthetic module the expression is parsed in.
const PREFIX: &str = "MODULE rapid_eval_\n  CONST anytype rapid_eval_ := ";
const SUFFIX: &str = ";\nENDMODULE\n";
const EVAL_PATH: &str = "<expression>";

pub fn run(args: EvalArgs) -> ExitCode {
    let expr_text = args.expr.trim();
    match evaluate(
        &crate::project::Disk,
        expr_text,
        args.file.as_deref(),
        args.initial,
    ) {
        Err(Failure::Syntax(e)) => syntax_error(&e, expr_text, args.format),
        Err(Failure::Usage(message)) => {
            let _ = writeln!(anstream::stderr(), "rapid: eval: {message}");
            ExitCode::from(2)
        }
        Err(Failure::Eval(e)) => report(&Err(e), args.format),
        Ok(value) => report(&Ok(value), args.format),
    }
}

/// Why an expression has no value.
pub enum Failure {
    /// It does not parse.
    Syntax(SyntaxError),
    /// It is empty, not one expression, or its program cannot be read.
    Usage(String),
    /// Its evaluation fails (a run-time error, data that is not constant,
    /// an unknown name).
    Eval(EvalError),
}

impl std::fmt::Display for Failure {
    /// The failure in one line: `does not parse at column 4: ...`,
    /// `ERR_DIVZERO: ...`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Syntax(e) => match e.column {
                Some(column) => write!(f, "does not parse at column {column}: {}", e.message),
                None => f.write_str(&e.message),
            },
            Failure::Usage(m) => f.write_str(m),
            Failure::Eval(e) => write!(f, "{}: {}", e.code.name(), e.message),
        }
    }
}

/// The value of `expr_text` as the controller computes it, alone or (with
/// `file`, a module or a folder read through `env`) with a program's data;
/// `initial`: VAR and PERS data at their initial values.
pub fn evaluate(
    env: &dyn crate::project::Environment,
    expr_text: &str,
    file: Option<&Path>,
    initial: bool,
) -> Result<Evaluation, Failure> {
    let expr = Expression::parse(expr_text)?;
    let (task, at) = match file {
        None => (
            Arc::new(Task::new(String::new(), vec![expr.unit.clone()], None)),
            None,
        ),
        Some(path) => {
            program(env, path).map_err(|m| Failure::Usage(format!("{}: {m}", path.display())))?
        }
    };
    let options = if initial {
        EnvOptions::initial_values()
    } else {
        EnvOptions::default()
    };
    expr.value_in(&task, at, None, options)
}

/// An expression parsed (in a small synthetic module), to be evaluated in
/// a task.
pub struct Expression {
    unit: Arc<Unit>,
    text: String,
}

impl Expression {
    /// Parses `text` (blanks around it ignored): an empty text, or one that
    /// is not a single expression, is refused.
    pub fn parse(text: &str) -> Result<Expression, Failure> {
        let text = text.trim();
        if text.is_empty() {
            return Err(Failure::Usage("the expression is empty".to_owned()));
        }
        let source = format!("{PREFIX}{text}{SUFFIX}");
        let unit = Arc::new(Unit::new(EVAL_PATH.to_owned(), source, None));
        check_syntax(&unit, text).map_err(Failure::Syntax)?;
        Ok(Expression {
            unit,
            text: text.to_owned(),
        })
    }

    /// Its value in `task`, names resolving at `at` (a unit of the task and
    /// an offset in it; `None`: the task's global data); `expected`: the
    /// type an aggregate (`[1, 2, 3]`) is read as.
    pub fn value_in(
        &self,
        task: &Task,
        at: Option<(usize, usize)>,
        expected: Option<&rapid_evaluator::Type>,
        options: EnvOptions,
    ) -> Result<Evaluation, Failure> {
        let Some(node) = expression_node(&self.unit, &self.text) else {
            return Err(Failure::Usage("not a single expression".to_owned()));
        };
        let module = at.and_then(|(unit, offset)| {
            let m = task.units.get(unit)?.items.module_at(offset)?;
            Some((unit, m))
        });
        let expr = lower_with(node, &self.unit.text, &|name| {
            consteval::is_builtin_call(task, module, name)
        });
        consteval::eval_in(task, at, &expr, expected, options).map_err(Failure::Eval)
    }
}

/// Prints the value or the error; the exit code.
fn report(result: &Result<Evaluation, EvalError>, format: Format) -> ExitCode {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut stderr = anstream::stderr();
    let written = match (result, format) {
        (Ok(e), Format::Human) => {
            if !e.initial_values_used.is_empty() {
                let _ = writeln!(
                    stderr,
                    "rapid: eval: note: computed from the initial value of {} (not constant: it may differ at run time)",
                    names(&e.initial_values_used)
                );
            }
            writeln!(out, "{}", e.value)
        }
        (Ok(e), Format::Json) => {
            let mut v = serde_json::json!({
                "type": consteval::value_type(&e.value),
                "value": e.value.to_string(),
            });
            if !e.initial_values_used.is_empty() {
                v["initial_values"] = serde_json::json!(e.initial_values_used);
            }
            writeln!(out, "{v}")
        }
        (Err(e), Format::Human) => {
            let _ = writeln!(stderr, "error: {}: {}", e.code.name(), e.message);
            Ok(())
        }
        (Err(e), Format::Json) => {
            let v = serde_json::json!({
                "error": {
                    "code": e.code.name(),
                    "message": e.message,
                    "runtime": e.code.is_runtime(),
                }
            });
            writeln!(out, "{v}")
        }
    };
    if let Err(e) = written.and_then(|()| out.flush())
        && e.kind() != std::io::ErrorKind::BrokenPipe
    {
        let _ = writeln!(stderr, "rapid: eval: cannot write the result: {e}");
        return ExitCode::from(2);
    }
    if result.is_ok() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

fn names(list: &[String]) -> String {
    let quoted: Vec<String> = list.iter().map(|n| format!("`{n}`")).collect();
    quoted.join(", ")
}

/// The expression's node in the synthetic module: the initial value, which
/// must span the whole expression.
fn expression_node<'u>(unit: &'u Unit, expr: &str) -> Option<tree_sitter::Node<'u>> {
    let start = PREFIX.len();
    let end = start + expr.len();
    let mut node = unit
        .tree()
        .root_node()
        .named_descendant_for_byte_range(start, end)?;
    loop {
        if node.byte_range() == (start..end) && is_expression(node.kind()) {
            let parent = node.parent()?;
            if parent.kind() == "data_declaration" {
                return Some(node);
            }
        }
        node = node.parent()?;
        if node.start_byte() < start || node.end_byte() > end {
            return None;
        }
    }
}

/// Syntax errors of the synthetic module, told in the user's text.
/// Why the expression cannot be evaluated as written.
pub struct SyntaxError {
    /// 1-based character column in the expression.
    pub column: Option<usize>,
    pub message: String,
}

fn check_syntax(unit: &Unit, expr: &str) -> Result<(), SyntaxError> {
    check_brackets(expr)?;
    if let Some(d) = unit.syntax.first() {
        let offset = d.range.start.saturating_sub(PREFIX.len()).min(expr.len());
        let column = expr.get(..offset).map_or(offset, |s| s.chars().count()) + 1;
        return Err(SyntaxError {
            column: Some(column),
            message: in_expression_words(&d.message, offset >= expr.len(), expr),
        });
    }
    if expression_node(unit, expr).is_none() {
        return Err(SyntaxError {
            column: None,
            message: "the text is not a single RAPID expression".to_owned(),
        });
    }
    Ok(())
}

/// Brackets and strings, checked before the grammar: an unclosed `(` is
/// told with its place and what may follow it, where the grammar would
/// speak of the synthetic module around the expression.
fn check_brackets(expr: &str) -> Result<(), SyntaxError> {
    let chars: Vec<char> = expr.chars().collect();
    let err = |column: usize, message: String| SyntaxError {
        column: Some(column),
        message,
    };
    let closing = |open: char| match open {
        '(' => ')',
        '[' => ']',
        _ => '}',
    };
    let mut open: Vec<(char, usize)> = Vec::new();
    let mut string: Option<usize> = None;
    let mut i = 0;
    while i < chars.len() {
        let (c, column) = (chars[i], i + 1);
        if string.is_some() {
            if c == '"' {
                // `""` is a quote inside the string.
                if chars.get(i + 1) == Some(&'"') {
                    i += 1;
                } else {
                    string = None;
                }
            }
            i += 1;
            continue;
        }
        let next = chars[i + 1..].iter().find(|c| !c.is_whitespace());
        match c {
            '"' => string = Some(column),
            '(' | '[' | '{' => open.push((c, column)),
            ')' | ']' | '}' => match open.pop() {
                None => {
                    return Err(err(
                        column,
                        format!("unexpected `{c}`: no bracket before it to close"),
                    ));
                }
                Some((o, at)) if closing(o) != c => {
                    return Err(err(
                        column,
                        format!(
                            "expected `{}` to close the `{o}` of column {at}, found `{c}`",
                            closing(o)
                        ),
                    ));
                }
                Some(_) => {}
            },
            ',' if matches!(next, Some(')' | ']' | '}')) => {
                return Err(err(
                    column,
                    format!(
                        "expected an argument after `,`, found `{}`",
                        next.copied().unwrap_or(')')
                    ),
                ));
            }
            _ => {}
        }
        i += 1;
    }
    if let Some(at) = string {
        return Err(err(at, "this string has no closing `\"`".to_owned()));
    }
    if let Some(&(o, at)) = open.last() {
        let what = if chars[at..].iter().all(|c| c.is_whitespace()) {
            match o {
                '(' => "an argument or `)`".to_owned(),
                '[' => "a value or `]`".to_owned(),
                _ => "an index or `}`".to_owned(),
            }
        } else {
            format!("`{}`", closing(o))
        };
        return Err(err(
            chars.len() + 1,
            format!(
                "expected {what} after the `{o}` of column {at}, found the end of the expression"
            ),
        ));
    }
    Ok(())
}

/// A syntax message about the synthetic module, said of the expression:
/// its `;` and `ENDMODULE` are the expression's end.
fn in_expression_words(message: &str, at_end: bool, expr: &str) -> String {
    if at_end {
        let last = expr
            .trim_end()
            .chars()
            .last()
            .map(|c| format!(" after `{c}`"))
            .unwrap_or_default();
        if message.starts_with("missing a name") || message.starts_with("missing a number") {
            return format!("expected an operand{last}, found the end of the expression");
        }
        return format!("the expression ends too early{last}: {message}");
    }
    match message.strip_prefix("expected `;`, found ") {
        Some(found) => format!("unexpected {found}: the expression is complete before it"),
        None => message.replace("`ENDMODULE`", "the end of the expression"),
    }
}

/// Reports an expression that does not parse; exit code 2.
fn syntax_error(e: &SyntaxError, expr: &str, format: Format) -> ExitCode {
    match format {
        Format::Json => {
            let v = serde_json::json!({
                "error": {
                    "code": "syntax-error",
                    "message": e.message,
                    "column": e.column,
                }
            });
            let _ = writeln!(std::io::stdout().lock(), "{v}");
        }
        Format::Human => {
            let mut stderr = anstream::stderr();
            let _ = match e.column {
                Some(column) => writeln!(
                    stderr,
                    "rapid: eval: the expression does not parse at column {column}: {}\n  {expr}\n  {}^",
                    e.message,
                    " ".repeat(column - 1)
                ),
                None => writeln!(stderr, "rapid: eval: {}", e.message),
            };
        }
    }
    ExitCode::from(2)
}

/// A task, and the unit and offset where names resolve (`None`: the
/// task's globals).
pub type Program = (Arc<Task>, Option<(usize, usize)>);

/// The task of `path` (a module, or a folder) and where names resolve: in a
/// module, at its start; in a folder, the task's globals.
fn program(env: &dyn crate::project::Environment, path: &Path) -> Result<Program, String> {
    let around =
        crate::project::load_around(env, &[path.to_owned()]).map_err(|(_, e)| e.to_string())?;
    let mut workspace = around.loaded.workspace;
    place(
        env,
        path,
        &mut workspace,
        &around.files,
        &around.loaded.read,
    )
}

/// The task of `path` in a loaded `workspace` (`files` were found and
/// `read` in its loading) and where names resolve: for a module, its task
/// at the module's start; for a folder, its own task's globals (the task
/// of a module directly in it, else the only task under it).
pub fn place(
    env: &dyn crate::project::Environment,
    path: &Path,
    workspace: &mut rapid_analyzer::workspace::Workspace,
    files: &[PathBuf],
    read: &[Result<crate::project::SourceFile, crate::project::Skip>],
) -> Result<Program, String> {
    let is_file = matches!(env.kind(path), Ok(crate::project::Kind::File(_)));
    if let Some(Err(why)) = files
        .iter()
        .position(|f| f == path)
        .and_then(|i| read.get(i))
        .filter(|_| is_file)
    {
        return Err(why.to_string());
    }
    if is_file {
        let me = env.name(path);
        let task = workspace.task_of(&me);
        let unit = task
            .units
            .iter()
            .position(|u| u.path == me)
            .ok_or("not a RAPID module")?;
        let module = task.units[unit]
            .items
            .modules
            .first()
            .ok_or("no module found in the file")?;
        let at = Some((unit, module.name_range.start));
        return Ok((task, at));
    }
    // The folder's own task: the task of a module directly in it.
    let wanted = files
        .iter()
        .find(|f| f.parent() == Some(path))
        .map(|f| workspace.task_key(&env.name(f)));
    let tasks = workspace.tasks();
    let task = match tasks.iter().find(|t| Some(&t.key) == wanted.as_ref()) {
        Some(t) => t.clone(),
        None if tasks.len() == 1 => tasks[0].clone(),
        None if tasks.is_empty() => return Err("no RAPID modules found".to_owned()),
        None => {
            let keys: Vec<&str> = tasks.iter().map(|t| t.key.as_str()).collect();
            return Err(crate::run::load::several_tasks(&keys));
        }
    };
    Ok((task, None))
}
