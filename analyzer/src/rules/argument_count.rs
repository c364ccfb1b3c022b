use std::ops::Range;

use crate::check::Cx;
use crate::sema::signature::{Param, Signature};

crate::declare_rule! {
    /// Too few or too many arguments for a routine's required parameters.
    ///
    /// ### What it checks
    /// Every required parameter must get an argument, and there may not be more
    /// positional arguments than required parameters. Optional arguments are
    /// written with `\` and do not count here.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// MoveL p10, v100, fine;     ! the Tool argument is missing
    /// ```
    pub static RULE = ("E301", "argument-count", Error);
}

/// A positional argument at `range` beyond the routine's parameters.
pub(crate) fn too_many(cx: &mut Cx<'_>, sig: &Signature, range: Range<usize>) {
    let positional = sig.params.iter().filter(|p| p.positional()).count();
    cx.report(
        &RULE,
        range,
        format!(
            "too many arguments: `{}` takes {positional} without the optional ones",
            sig.name
        ),
    );
}

/// The required parameters (indexes into `sig`'s) a call at `range`
/// leaves out.
pub(crate) fn missing(cx: &mut Cx<'_>, sig: &Signature, missing: &[usize], range: Range<usize>) {
    let missing: Vec<&Param> = missing.iter().filter_map(|&i| sig.params.get(i)).collect();
    if missing.is_empty() {
        return;
    }
    let list: Vec<String> = missing
        .iter()
        .map(|p| format!("{} ({})", p.name, p.ty))
        .collect();
    cx.report(
        &RULE,
        range,
        format!(
            "`{}` is missing {} argument{}: {}",
            sig.name,
            if missing.len() == 1 { "an" } else { "required" },
            if missing.len() == 1 { "" } else { "s" },
            list.join(", ")
        ),
    );
}
