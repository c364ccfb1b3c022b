//! The evaluation environment over a task: each module's scope (its own
//! items, the task's globals, predefined data and signals), a routine's scope
//! around an offset, and the catalogue's predefined data.

use super::*;

/// State shared by every scope of one [`with_env`] call.
pub(super) struct Shared<'t> {
    task: &'t Task,
    options: EnvOptions,
    /// Index of each unit's first module in the scope list.
    offsets: Vec<usize>,
    types: OnceCell<crate::ty::Types<'t>>,
    /// Lowered initial values of module data, kept across calls.
    inits: Option<&'t InitCache>,
}

impl<'t> Shared<'t> {
    pub(super) fn new(
        task: &'t Task,
        options: EnvOptions,
        inits: Option<&'t InitCache>,
    ) -> Shared<'t> {
        let mut offsets = Vec::with_capacity(task.units.len());
        let mut n = 0;
        for u in task.units.iter() {
            offsets.push(n);
            n += u.items.modules.len();
        }
        Shared {
            task,
            options,
            offsets,
            types: OnceCell::new(),
            inits,
        }
    }

    pub(super) fn index(&self, unit: usize, module: usize) -> Option<usize> {
        let count = self.task.unit(unit)?.items.modules.len();
        (module < count).then(|| self.offsets.get(unit).map(|o| o + module))?
    }

    /// Calls `f` with the syntax tree of `unit` (of this task): its own if
    /// in memory, else one parsed again and kept for the rest of the check
    /// that asks (a constant of another module is often read many times),
    /// or for this call only.
    pub(super) fn with_tree<R>(&self, unit: &Unit, f: impl FnOnce(&Tree) -> R) -> R {
        if unit.tree_loaded() {
            return unit.with_tree(f);
        }
        match self.inits {
            Some(inits) => f(&inits.tree_of(unit)),
            None => unit.with_tree(f),
        }
    }

    fn types(&self) -> &crate::ty::Types<'t> {
        self.types.get_or_init(|| self.task.types())
    }

    fn record_layout(&self, name: &str) -> Option<Vec<(String, Type)>> {
        record_layout_in(self.types(), name)
    }

    fn alias_of(&self, name: &str) -> Option<Type> {
        alias_in(self.types(), name)
    }

    /// The initial value to offer for data of this storage.
    fn offers_initial(&self, storage: Storage) -> bool {
        match storage {
            Storage::Const => true,
            Storage::Pers => self.options.pers_initial,
            Storage::Var => self.options.var_initial,
        }
    }
}

/// The components of the task's own record type `name` (the catalogue's
/// records are the evaluator's: a task's `RECORD` wins over a built-in
/// type of its name, as in [`Types::components`]).
fn record_layout_in(types: &Types<'_>, name: &str) -> Option<Vec<(String, Type)>> {
    match types.user(name) {
        Some(UserType::Record(r)) => Some(
            r.components
                .iter()
                .map(|(n, t, _)| {
                    let ty = t.as_ref().map_or("?", |t| t.name.as_str());
                    (n.clone(), Type::named(ty))
                })
                .collect(),
        ),
        _ => None,
    }
}

/// The type the task's own alias type `name` stands for.
fn alias_in(types: &Types<'_>, name: &str) -> Option<Type> {
    match types.user(name) {
        Some(UserType::Alias(a)) => a.of.as_ref().map(|t| Type::named(&t.name)),
        _ => None,
    }
}

/// The types of a task as the evaluator asks for them (the task's records
/// and aliases; the evaluator knows its catalogue view's), computed once and
/// owned: for a reader that keeps them while it runs the task's code (the
/// interpreter coerces values and builds aggregates with them). Names
/// resolve to nothing.
pub struct TypeEnv {
    records: crate::names::NameMap<Option<Vec<(String, Type)>>>,
    aliases: crate::names::NameMap<Option<Type>>,
    /// The task's types that have a built-in type's name (folded): rare,
    /// so a built-in type is found without a lookup here.
    shadowing: Vec<String>,
    catalogue: &'static Catalogue,
}

impl TypeEnv {
    /// The types of `task` (its user types are looked up now; the
    /// catalogue's on demand).
    pub fn of(task: &Task) -> TypeEnv {
        let types = task.types();
        let mut records = crate::names::NameMap::default();
        let mut aliases = crate::names::NameMap::default();
        for unit in task.units.iter() {
            for m in &unit.items.modules {
                for r in &m.records {
                    records
                        .entry(fold(&r.name))
                        .or_insert_with(|| record_layout_in(&types, &r.name));
                }
                for a in &m.aliases {
                    aliases
                        .entry(fold(&a.name))
                        .or_insert_with(|| alias_in(&types, &a.name));
                }
            }
        }
        let shadowing = records
            .keys()
            .chain(aliases.keys())
            .filter(|n| task.catalogue.datatype(n).is_some())
            .cloned()
            .collect();
        TypeEnv {
            records,
            aliases,
            shadowing,
            catalogue: task.catalogue,
        }
    }
}

impl Env for TypeEnv {
    fn lookup(&self, _name: &str) -> Lookup<'_> {
        Lookup::Unknown
    }

    // Asked for every type a value is converted to, built-in ones first
    // of all: no allocation when the task declares no type of the name.
    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        if self.records.is_empty() {
            return None;
        }
        crate::names::with_folded(type_name, |k| self.records.get(k).cloned().flatten())
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        if self.aliases.is_empty() {
            return None;
        }
        crate::names::with_folded(type_name, |k| self.aliases.get(k).cloned().flatten())
    }

    fn declares_type(&self, type_name: &str) -> bool {
        !self.shadowing.is_empty()
            && crate::names::with_folded(type_name, |k| self.shadowing.iter().any(|s| s == k))
    }

    fn catalogue(&self) -> &Catalogue {
        self.catalogue
    }
}

/// The names of one module (or, with `module` `None`, of the task's
/// globals only).
pub(super) struct ModuleScope<'s, 't> {
    shared: &'s Shared<'t>,
    unit: usize,
    module: Option<usize>,
    /// Every module scope of the task, to evaluate a constant where it is
    /// declared.
    pub(super) all: OnceCell<&'s [ModuleScope<'s, 't>]>,
    /// Guards the evaluation of array sizes against cycles.
    dims_depth: Cell<u32>,
}

impl<'s, 't> ModuleScope<'s, 't> {
    pub(super) fn new(shared: &'s Shared<'t>, unit: usize, module: Option<usize>) -> Self {
        ModuleScope {
            shared,
            unit,
            module,
            all: OnceCell::new(),
            dims_depth: Cell::new(0),
        }
    }

    /// Items visible from this module under `name`
    /// ([`crate::sema::scope::visible`], the checker's lookup too).
    fn visible(&self, name: &str) -> Vec<ItemRef> {
        crate::names::with_folded(name, |key| self.visible_folded(key))
    }

    fn visible_folded(&self, key: &str) -> Vec<ItemRef> {
        crate::sema::scope::visible(self.shared.task, self.unit, self.module, key)
    }

    fn scope_of(&self, unit: usize, module: usize) -> Option<&'s ModuleScope<'s, 't>> {
        let i = self.shared.index(unit, module)?;
        self.all.get()?.get(i)
    }

    fn is_builtin(&self, name: &str) -> bool {
        is_builtin_call(self.shared.task, self.module.map(|m| (self.unit, m)), name)
    }
}

impl Env for ModuleScope<'_, '_> {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        let task = self.shared.task;
        for r in self.visible(name) {
            let Some(d) = task.data(r) else {
                continue;
            };
            let Some(unit) = task.unit(r.unit) else {
                return Lookup::Unknown;
            };
            let Some(scope) = self.scope_of(r.unit, r.module) else {
                return Lookup::Unknown;
            };
            return data_lookup(
                self.shared,
                d,
                self.shared.inits.and_then(|c| c.slot(task, r)),
                unit,
                Some(scope),
                scope,
                &|n| scope.is_builtin(n),
                &scope.dims_depth,
            );
        }
        outside_the_task(task, name, self.shared.options)
    }

    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        self.shared.record_layout(type_name)
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        self.shared.alias_of(type_name)
    }

    /// The task's view: calls are bound with its RobotWare's signatures.
    fn catalogue(&self) -> &crate::catalogue::Catalogue {
        self.shared.task.catalogue
    }
}

/// Names the task does not declare: the catalogue's predefined data and
/// configured signals.
pub(super) fn outside_the_task<'a>(task: &Task, name: &str, options: EnvOptions) -> Lookup<'a> {
    if let Some(d) = task.catalogue.datum(name) {
        return catalogue_lookup(d, options);
    }
    let key = fold(name);
    if let Some(ty) = task.signals.as_ref().and_then(|s| s.get(&key)) {
        return Lookup::Variable {
            kind: VarKind::Var,
            ty: Type::named(*ty),
            initial: None,
            scope: None,
        };
    }
    Lookup::Unknown
}

/// The predefined data of the catalogue, whose values are RAPID literals
/// (the same in every view: it reads the whole catalogue).
pub(super) struct CatalogueEnv {
    options: EnvOptions,
}

pub(super) static CATALOGUE_ENV: CatalogueEnv = CatalogueEnv {
    options: EnvOptions {
        pers_initial: false,
        var_initial: false,
    },
};
pub(super) static CATALOGUE_ENV_INITIAL: CatalogueEnv = CatalogueEnv {
    options: EnvOptions {
        pers_initial: true,
        var_initial: true,
    },
};

impl Env for CatalogueEnv {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        match crate::catalogue::base().datum(name) {
            Some(d) => catalogue_lookup(d, self.options),
            None => Lookup::Unknown,
        }
    }
}

pub(super) fn catalogue_lookup<'a>(d: &'static Datum, options: EnvOptions) -> Lookup<'a> {
    let value = d
        .value
        .as_deref()
        .and_then(rapid_evaluator::parse_data_literal);
    let ty = Type::named(&d.ty);
    let scope: &'static dyn Env = if options.pers_initial || options.var_initial {
        &CATALOGUE_ENV_INITIAL
    } else {
        &CATALOGUE_ENV
    };
    let kind = match d.kind {
        DatumKind::Const => {
            return match value {
                Some(e) => Lookup::Constant {
                    expr: Cow::Owned(e),
                    ty,
                    scope: Some(scope),
                },
                // Let the evaluator's own table answer (pi, STR_*, ...).
                None => Lookup::Unknown,
            };
        }
        DatumKind::Pers => VarKind::Pers,
        DatumKind::Var => VarKind::Var,
    };
    let offered = match kind {
        VarKind::Pers => options.pers_initial,
        VarKind::Var => options.var_initial,
    };
    Lookup::Variable {
        kind,
        ty,
        initial: value.filter(|_| offered).map(Cow::Owned),
        scope: Some(scope),
    }
}

/// What a data declaration gives the evaluator. `scope` is where names in
/// its initial value resolve (`None`: the asking environment); `dims_env`
/// evaluates its array sizes. `slot` keeps its lowered initial value.
#[allow(clippy::too_many_arguments)]
pub(super) fn data_lookup<'a>(
    shared: &Shared<'_>,
    d: &DataDecl,
    slot: Option<&'a OnceCell<Option<Expr>>>,
    unit: &Unit,
    scope: Option<&'a dyn Env>,
    dims_env: &dyn Env,
    is_builtin: &dyn Fn(&str) -> bool,
    dims_depth: &Cell<u32>,
) -> Lookup<'a> {
    let ty = decl_type(shared, d, unit, dims_env, dims_depth);
    let lower = || {
        let r = d.init.as_ref()?;
        shared.with_tree(unit, |tree| {
            expression_in(tree, r.clone()).map(|n| lower_with(n, &unit.text, is_builtin))
        })
    };
    let init = || -> Option<Cow<'a, Expr>> {
        match slot {
            Some(slot) => slot.get_or_init(lower).as_ref().map(Cow::Borrowed),
            None => lower().map(Cow::Owned),
        }
    };
    let kind = match d.storage {
        Storage::Const => {
            return Lookup::Constant {
                expr: init().unwrap_or(Cow::Owned(Expr::Unknown)),
                ty,
                scope,
            };
        }
        Storage::Pers => VarKind::Pers,
        Storage::Var => VarKind::Var,
    };
    Lookup::Variable {
        kind,
        ty,
        initial: if shared.offers_initial(d.storage) {
            init()
        } else {
            None
        },
        scope,
    }
}

/// The declared type of data, with the array sizes that are known (a size
/// that is not a constant is 0: not checked).
pub(super) fn decl_type(
    shared: &Shared<'_>,
    d: &DataDecl,
    unit: &Unit,
    env: &dyn Env,
    depth: &Cell<u32>,
) -> Type {
    let name = d.ty.as_ref().map_or("?", |t| t.name.as_str());
    let dims = d
        .dims
        .iter()
        .map(|r| array_size(shared, unit, r.clone(), env, depth))
        .collect();
    Type::array(name, dims)
}

pub(super) fn array_size(
    shared: &Shared<'_>,
    unit: &Unit,
    range: Range<usize>,
    env: &dyn Env,
    depth: &Cell<u32>,
) -> usize {
    let text = unit.text.get(range.clone()).unwrap_or_default().trim();
    if let Ok(n) = text.parse::<usize>() {
        return n;
    }
    // A size given by a constant: evaluate it, but never through a chain of
    // sizes (a constant whose size refers to itself).
    if depth.get() >= 2 {
        return 0;
    }
    let lowered = shared.with_tree(unit, |tree| {
        expression_in(tree, range).map(|n| crate::lower::lower(n, &unit.text))
    });
    let Some(expr) = lowered else {
        return 0;
    };
    depth.set(depth.get() + 1);
    let v = rapid_evaluator::eval_as(&expr, Some(&Type::named("num")), env);
    depth.set(depth.get() - 1);
    match v.ok().and_then(|v| v.as_f64()) {
        Some(x) if x >= 1.0 && x.fract() == 0.0 && x <= 1e6 => x as usize,
        _ => 0,
    }
}

/// The outermost expression node of `tree` spanning exactly `range`.
pub(super) fn expression_in(tree: &Tree, range: Range<usize>) -> Option<Node<'_>> {
    path_to(tree.root_node(), range.clone())
        .into_iter()
        .map(|(n, _)| n)
        .find(|n| n.byte_range() == range && is_expression(crate::syntax_util::kind(*n)))
}

/// A node with the field of its parent that holds it.
pub(super) type Step<'t> = (Node<'t>, Option<&'t str>);

/// The nodes from `root` down to the smallest one that contains `range`,
/// each with its field name. (Walking down with a cursor is cheap;
/// `Node::parent` searches from the root each time.)
pub(super) fn path_to(root: Node<'_>, range: Range<usize>) -> Vec<Step<'_>> {
    let mut path = vec![(root, None)];
    let mut cursor = root.walk();
    'down: while cursor.goto_first_child_for_byte(range.start).is_some() {
        loop {
            let n = cursor.node();
            if n.start_byte() > range.start {
                break 'down;
            }
            let touches_only = n.end_byte() == range.start && range.end > range.start;
            if n.end_byte() >= range.end && !touches_only {
                path.push((n, cursor.field_name()));
                continue 'down;
            }
            if !cursor.goto_next_sibling() {
                break 'down;
            }
        }
    }
    path
}

/// The names of a routine (data, parameters, `FOR` variables around the
/// offset), in front of its module's.
pub(super) struct RoutineScope<'s, 't> {
    pub(super) module: &'s ModuleScope<'s, 't>,
    pub(super) unit: &'t Unit,
    pub(super) names: crate::sema::scope::RoutineScope<'t>,
    pub(super) dims_depth: Cell<u32>,
}

impl Env for RoutineScope<'_, '_> {
    fn lookup(&self, name: &str) -> Lookup<'_> {
        let key = fold(name);
        let r = &self.names;
        {
            if r.for_vars.iter().any(|(v, _)| *v == key) {
                return Lookup::Variable {
                    kind: VarKind::Var,
                    ty: Type::named("num"),
                    initial: None,
                    scope: None,
                };
            }
            if let Some(d) = r.locals.get(&key) {
                return data_lookup(
                    self.module.shared,
                    d,
                    None,
                    self.unit,
                    None,
                    self,
                    &|n| self.module.is_builtin(n),
                    &self.dims_depth,
                );
            }
            if let Some(p) = r.params.get(&key) {
                let ty = p.ty.as_ref().map_or("?", |t| t.name.as_str());
                return Lookup::Variable {
                    kind: if p.mode == Mode::Pers {
                        VarKind::Pers
                    } else {
                        VarKind::Var
                    },
                    ty: Type::array(ty, vec![0; usize::from(p.dims)]),
                    initial: None,
                    scope: None,
                };
            }
        }
        self.module.lookup(name)
    }

    fn record_layout(&self, type_name: &str) -> Option<Vec<(String, Type)>> {
        self.module.record_layout(type_name)
    }

    fn alias_of(&self, type_name: &str) -> Option<Type> {
        self.module.alias_of(type_name)
    }

    fn catalogue(&self) -> &crate::catalogue::Catalogue {
        self.module.catalogue()
    }
}
