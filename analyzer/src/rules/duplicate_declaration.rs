use std::collections::HashMap;
use std::ops::Range;

use crate::check::Cx;
use crate::diagnostic::Diagnostic;
use crate::names::fold;

crate::declare_rule! {
    /// Two declarations of the same name in one scope.
    ///
    /// ### What it checks
    /// Within one module (data, routines, records and aliases share one name space)
    /// and within one routine (parameters and routine data), every name must be
    /// declared once. Names are compared without regard to case.
    ///
    /// ### Why
    /// The controller rejects the module.
    ///
    /// ### Example
    /// ```rapid
    /// VAR num count;
    /// VAR num Count;    ! same name as count
    /// ```
    pub static RULE = ("E106", "duplicate-declaration", Error);
}

pub(crate) fn report(cx: &mut Cx<'_>, names: Vec<(&str, Range<usize>)>, scope: &str) {
    let mut first: HashMap<String, Range<usize>> = HashMap::new();
    for (name, range) in names {
        match first.get(&fold(name)) {
            Some(prev) => {
                let d =
                    Diagnostic::new(&RULE, range, format!("`{name}` is declared twice {scope}"))
                        .with_related(crate::diagnostic::Related {
                            file: None,
                            range: prev.clone(),
                            message: "first declared here".into(),
                        });
                cx.report_with(d);
            }
            None => {
                first.insert(fold(name), range);
            }
        }
    }
}

/// The label `name` declared again at `range`, first at `first`.
pub(crate) fn report_label(cx: &mut Cx<'_>, name: &str, range: Range<usize>, first: Range<usize>) {
    let d = Diagnostic::new(
        &RULE,
        range,
        format!("the label `{name}` is declared twice in this routine"),
    )
    .with_related(crate::diagnostic::Related {
        file: None,
        range: first,
        message: "first declared here".into(),
    });
    cx.report_with(d);
}
