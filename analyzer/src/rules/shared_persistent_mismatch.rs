use crate::check::Cx;
use crate::diagnostic::Related;
use crate::items::{DataDecl, Scope, Storage};
use crate::names::fold;
use crate::task::{Item, SharedPers};

crate::declare_rule! {
    /// A persistent that another task of the controller declares differently.
    ///
    /// Another task of the same controller declares the persistent with a
    /// different type or different dimensions.
    ///
    /// ### What it checks
    /// A system-global `PERS` (without `TASK` or `LOCAL`) is one datum for
    /// the whole controller: every task that declares it shares its value.
    /// In a backup (`RAPID/TASKn` folders), each such persistent must have
    /// the same data type and the same array sizes in every task. An `ALIAS`
    /// and its base type count as the same type. `TASK PERS` data are not
    /// shared and are not compared.
    ///
    /// ### Why
    /// The controller refuses to load the second module: one datum cannot
    /// have two types.
    ///
    /// ### Example
    /// ```rapid
    /// ! RAPID/TASK1/PROGMOD/Main.mod
    /// PERS num partCount := 0;
    /// ! RAPID/TASK2/PROGMOD/Main.mod
    /// PERS dnum partCount := 0;   ! the same persistent as a dnum
    /// ```
    pub static RULE = ("E109", "shared-persistent-mismatch", Error);
}

/// Reports `decl` (module data of the checked unit) when another task of the
/// controller declares the same system-global persistent differently.
pub(crate) fn check(cx: &mut Cx<'_>, decl: &DataDecl) {
    if decl.storage != Storage::Pers || decl.scope != Scope::Global || cx.task.shared.is_empty() {
        return;
    }
    let Some(ty) = &decl.ty else { return };
    let Some(others) = cx.task.shared.get(&fold(&decl.name)) else {
        return;
    };
    let own_alias = is_alias(cx, &ty.name);
    let dims: Vec<&str> = decl
        .dims
        .iter()
        .map(|r| cx.text.get(r.clone()).unwrap_or_default().trim())
        .collect();
    let Some(other) = others
        .iter()
        .filter(|o| o.task != cx.task.key)
        .find(|o| differs(&ty.name, own_alias, &dims, o))
    else {
        return;
    };
    let here = if dims.is_empty() {
        ty.name.clone()
    } else {
        format!("{}{{{}}}", ty.name, dims.join(","))
    };
    let task = other.task.rsplit('/').next().unwrap_or(&other.task);
    let mut d = crate::diagnostic::Diagnostic::new(
        &RULE,
        decl.name_range.clone(),
        format!(
            "the persistent `{}` is `{here}` here but `{}` in {task}; the tasks of a controller share it, so the declarations must agree",
            decl.name,
            other.display()
        ),
    );
    d.related.push(Related {
        file: Some(other.path.clone()),
        range: other.name_range.clone(),
        message: format!("{task} declares `{}` as `{}`", other.name, other.display()),
    });
    cx.report_with(d);
}

fn is_alias(cx: &Cx<'_>, name: &str) -> bool {
    let folded = fold(name);
    cx.task
        .globals
        .refs(&folded)
        .chain(cx.task.locals.refs(&folded))
        .any(|r| matches!(r.item, Item::Alias(_)))
}

/// Whether two declarations of a shared persistent cannot be the same
/// datum: different types (neither an alias), a different number of
/// dimensions, or different sizes where both are written as numbers.
fn differs(ty: &str, alias: bool, dims: &[&str], other: &SharedPers) -> bool {
    if !alias && !other.alias && !ty.eq_ignore_ascii_case(&other.ty) {
        return true;
    }
    if dims.len() != other.dims.len() {
        return true;
    }
    dims.iter()
        .zip(&other.dims)
        .any(|(a, b)| match (a.parse::<u64>(), b.parse::<u64>()) {
            (Ok(a), Ok(b)) => a != b,
            _ => false,
        })
}
