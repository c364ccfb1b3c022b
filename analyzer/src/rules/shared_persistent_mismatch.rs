use crate::check::Cx;
use crate::diagnostic::Related;
use crate::items::{DataDecl, Scope, Storage};
use crate::names::fold;
use crate::task::{Item, SharedPers, Task};

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
    if cx.task.shared.is_empty() {
        return;
    }
    let Some(ty) = &decl.ty else { return };
    let Some(other) = elsewhere(cx.task, decl)
        .into_iter()
        .find(|o| !same_datum(cx.task, cx.text, decl, o))
    else {
        return;
    };
    let here = own_display(cx.text, decl, &ty.name);
    let task = task_name(other);
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

/// The declarations in the other tasks of the controller of the
/// system-global persistent `decl` (module data of `task`), if it is one:
/// a `PERS` neither `TASK` nor `LOCAL`, in a backup's task folder.
pub(crate) fn elsewhere<'t>(task: &'t Task, decl: &DataDecl) -> Vec<&'t SharedPers> {
    if decl.storage != Storage::Pers || decl.scope != Scope::Global {
        return Vec::new();
    }
    task.shared
        .get(&fold(&decl.name))
        .map(|all| all.iter().filter(|o| o.task != task.key).collect())
        .unwrap_or_default()
}

/// Whether `other` declares the same datum as `decl` (of `task`, whose
/// text is `text`): the same type (or an alias on either side) and the
/// same dimensions.
pub(crate) fn same_datum(task: &Task, text: &str, decl: &DataDecl, other: &SharedPers) -> bool {
    let Some(ty) = &decl.ty else { return true };
    let dims: Vec<&str> = decl
        .dims
        .iter()
        .map(|r| text.get(r.clone()).unwrap_or_default().trim())
        .collect();
    !differs(&ty.name, is_alias(task, &ty.name), &dims, other)
}

/// The type of `decl` as RAPID writes it, with its dimensions.
pub(crate) fn own_display(text: &str, decl: &DataDecl, ty: &str) -> String {
    let dims: Vec<&str> = decl
        .dims
        .iter()
        .map(|r| text.get(r.clone()).unwrap_or_default().trim())
        .collect();
    if dims.is_empty() {
        ty.to_owned()
    } else {
        format!("{ty}{{{}}}", dims.join(","))
    }
}

/// The task's folder name (`TASK2`) of a declaration elsewhere.
pub(crate) fn task_name(other: &SharedPers) -> &str {
    other.task.rsplit('/').next().unwrap_or(&other.task)
}

fn is_alias(task: &Task, name: &str) -> bool {
    let folded = fold(name);
    task.globals
        .refs(&folded)
        .chain(task.locals.refs(&folded))
        .any(|r| matches!(r.item, Item::Alias(_)))
}

/// Whether two declarations of a shared persistent cannot be the same
/// datum: different types (neither an alias), a different number of
/// dimensions, or different sizes where both are written as numbers.
fn differs(ty: &str, alias: bool, dims: &[&str], other: &SharedPers) -> bool {
    if !alias && !other.alias && !crate::names::same(ty, &other.ty) {
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
