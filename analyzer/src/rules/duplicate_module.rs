use crate::check::Cx;
use crate::diagnostic::Diagnostic;
use crate::items::Module;
use crate::names::same;

crate::declare_rule! {
    /// Two files of one task declare a module of the same name.
    ///
    /// ### What it checks
    /// A task holds one module of each name. When two files of a backup's task
    /// folder (or of one `.pgf` program) declare the same module, only one of
    /// them can be loaded: the later file (by path) is reported once, naming the
    /// other. Each version is checked on its own against the rest of the task,
    /// so their shared names are not reported as ambiguous. In a plain folder,
    /// versions of a module side by side are common and are not reported.
    ///
    /// ### Why
    /// Loading the second file fails, or replaces the first: which version the
    /// controller runs depends on the order of loading.
    ///
    /// ### Example
    /// ```rapid
    /// ! RAPID/TASK1/PROGMOD/MainModule.mod
    /// MODULE MainModule ... ENDMODULE
    /// ! RAPID/TASK1/PROGMOD/MainModule_old.mod
    /// MODULE MainModule ... ENDMODULE     ! the same module again
    /// ```
    pub static RULE = ("W207", "duplicate-module", Warning);
}

/// Another file of the task (left out of this view of it) declares the
/// same module: reported in the later file, once.
pub(crate) fn check(cx: &mut Cx<'_>, module: &Module) {
    if !cx.task.is_certain() {
        return;
    }
    let first = cx.task.left_out().find_map(|u| {
        let m = u
            .items
            .modules
            .iter()
            .find(|m| same(&m.name, &module.name))?;
        (u.path < cx.unit.path).then(|| (u.path.clone(), m.name_range.clone()))
    });
    let Some((path, range)) = first else {
        return;
    };
    let file = path
        .rsplit(['/', '\\'])
        .next()
        .unwrap_or_default()
        .to_owned();
    let d = Diagnostic::new(
        &RULE,
        module.name_range.clone(),
        format!(
            "module {} is also declared in {file}: a task loads only one of them",
            module.name
        ),
    )
    .with_related(crate::diagnostic::Related {
        file: Some(path),
        range,
        message: format!("module {} declared here too", module.name),
    });
    cx.report_with(d);
}
