//! Types as the checker sees them, and the table of every type a task knows:
//! the catalogue's and the user's `RECORD` and `ALIAS` declarations.

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;
use std::rc::Rc;

use crate::catalogue::{Catalogue, TypeKind, ValueClass};
use crate::items::{AliasDecl, RecordDecl};
use crate::names::{NameHasher, fold, same, with_folded};

/// The type of a value, a data object or a parameter.
#[derive(Clone, Debug)]
pub enum Ty {
    /// Not known (an error was reported already, or the name is unresolved):
    /// compatible with everything, so one mistake gives one diagnostic.
    Unknown,
    /// A built-in routine's `anytype` parameter.
    Any,
    /// A named type, as spelt where it was declared.
    Named(String),
    /// An array of `dims` dimensions.
    Array(Box<Ty>, u8),
}

impl Ty {
    pub fn named(name: &str) -> Ty {
        Ty::Named(name.to_owned())
    }

    pub fn num() -> Ty {
        Ty::named("num")
    }

    pub fn bool() -> Ty {
        Ty::named("bool")
    }

    pub fn string() -> Ty {
        Ty::named("string")
    }

    /// An array of this type, or this type if `dims` is 0.
    pub fn array(self, dims: u8) -> Ty {
        match (dims, self) {
            (0, ty) => ty,
            (_, Ty::Unknown) => Ty::Unknown,
            (d, ty) => Ty::Array(Box::new(ty), d),
        }
    }

    pub fn is_unknown(&self) -> bool {
        matches!(self, Ty::Unknown | Ty::Any)
    }

    /// Is this the named type `name` (no alias resolution)?
    pub fn is(&self, name: &str) -> bool {
        matches!(self, Ty::Named(n) if same(n, name))
    }

    pub fn dims(&self) -> u8 {
        match self {
            Ty::Array(_, d) => *d,
            _ => 0,
        }
    }

    /// The element type of an array (the type itself otherwise).
    pub fn element(&self) -> &Ty {
        match self {
            Ty::Array(e, _) => e,
            t => t,
        }
    }
}

impl PartialEq for Ty {
    fn eq(&self, other: &Ty) -> bool {
        match (self, other) {
            (Ty::Unknown, Ty::Unknown) | (Ty::Any, Ty::Any) => true,
            (Ty::Named(a), Ty::Named(b)) => same(a, b),
            (Ty::Array(a, n), Ty::Array(b, m)) => n == m && a == b,
            _ => false,
        }
    }
}

impl fmt::Display for Ty {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ty::Unknown => f.write_str("unknown"),
            Ty::Any => f.write_str("anytype"),
            Ty::Named(n) => f.write_str(n),
            Ty::Array(e, d) => {
                let stars = vec!["*"; usize::from(*d)].join(",");
                write!(f, "{e}{{{stars}}}")
            }
        }
    }
}

/// A user-declared type.
#[derive(Clone, Copy, Debug)]
pub enum UserType<'a> {
    Record(&'a RecordDecl),
    Alias(&'a AliasDecl),
}

/// Every type a task knows.
pub struct Types<'a> {
    user: UserTypes<'a>,
    catalogue: &'static Catalogue,
    /// [`Types::components_shared`] and [`Types::accepts`] by type name
    /// as spelt: aggregates ask the same few questions over and over.
    memo: RefCell<Memo>,
}

/// Where [`Types`] finds the user's types.
enum UserTypes<'a> {
    /// Given as a list (the first of a name wins).
    Listed(HashMap<String, UserType<'a>>),
    /// A task's name index ([`crate::task::Task::user_type`]): nothing to
    /// build per check, whatever the size of the task.
    Task(&'a crate::task::Task),
}

impl<'a> UserTypes<'a> {
    fn get(&self, key: &str) -> Option<UserType<'a>> {
        match self {
            UserTypes::Listed(map) => map.get(key).copied(),
            UserTypes::Task(task) => task.user_type(key),
        }
    }
}

/// A record's components, in order: names and types.
pub type Components = Rc<[(String, Ty)]>;

/// See [`Types::info`].
#[derive(Clone, Copy)]
struct Info {
    exists: bool,
    /// A built-in type known by name only (its layout is not documented).
    opaque: bool,
    numeric: bool,
    signal: bool,
    boolean: bool,
    /// The folded name of the base type, interned in [`Memo::bases`].
    base_id: u32,
    base_numeric: bool,
    base_signal: bool,
}

/// A map by type name with the cheap [`NameHasher`].
type ByName<V> = HashMap<String, V, std::hash::BuildHasherDefault<NameHasher>>;

#[derive(Default)]
struct Memo {
    info: ByName<Info>,
    bases: ByName<u32>,
    components: ByName<Option<Components>>,
    /// By literal type: `num`, `string`, `bool`.
    accepts: [ByName<bool>; 3],
}

impl<'a> Types<'a> {
    pub fn new(
        user: impl IntoIterator<Item = UserType<'a>>,
        catalogue: &'static Catalogue,
    ) -> Types<'a> {
        let mut map = HashMap::new();
        for t in user {
            let name = match t {
                UserType::Record(r) => &r.name,
                UserType::Alias(a) => &a.name,
            };
            map.entry(fold(name)).or_insert(t);
        }
        Types {
            user: UserTypes::Listed(map),
            catalogue,
            memo: RefCell::default(),
        }
    }

    /// The types of `task`: its records and aliases as its name index finds
    /// them, and its catalogue's.
    pub fn of_task(task: &'a crate::task::Task) -> Types<'a> {
        Types {
            user: UserTypes::Task(task),
            catalogue: task.catalogue,
            memo: RefCell::default(),
        }
    }

    /// Is there a type of this name?
    pub fn exists(&self, name: &str) -> bool {
        self.info(name).exists
    }

    fn exists_uncached(&self, name: &str) -> bool {
        with_folded(name, |key| self.user.get(key).is_some())
            || self.catalogue.datatype(name).is_some()
            || name.eq_ignore_ascii_case("switch")
    }

    /// Is this a type the task knows, with a known layout (an unresolved
    /// type name is reported where it is declared, and behaves as unknown
    /// everywhere else; so does a built-in type known by name only)?
    pub fn is_known(&self, ty: &Ty) -> bool {
        match ty.element() {
            Ty::Named(n) => {
                let info = self.info(n);
                info.exists && !info.opaque
            }
            _ => false,
        }
    }

    pub fn user(&self, name: &str) -> Option<UserType<'a>> {
        with_folded(name, |key| self.user.get(key))
    }

    /// Follows aliases (user and built-in) to the type they stand for.
    pub fn base(&self, ty: &Ty) -> Ty {
        match ty {
            Ty::Named(name) => {
                let mut current = name.clone();
                for _ in 0..16 {
                    let next = match self.user(&current) {
                        Some(UserType::Alias(a)) => a.of.as_ref().map(|t| t.name.clone()),
                        Some(UserType::Record(_)) => None,
                        None => match self.catalogue.datatype(&current) {
                            // A type known by name only: its data are not
                            // type-checked.
                            Some(t) if !t.layout_known => return Ty::Unknown,
                            Some(t) => t.alias_of.clone(),
                            None => None,
                        },
                    };
                    match next {
                        Some(n) => current = n,
                        None => break,
                    }
                }
                Ty::Named(current)
            }
            Ty::Array(e, d) => Ty::Array(Box::new(self.base(e)), *d),
            other => other.clone(),
        }
    }

    /// The components of a record type, in order (after alias resolution).
    pub fn components(&self, ty: &Ty) -> Option<Vec<(String, Ty)>> {
        let Ty::Named(name) = self.base(ty) else {
            return None;
        };
        if let Some(UserType::Record(r)) = self.user(&name) {
            return Some(
                r.components
                    .iter()
                    .map(|(n, t, _)| {
                        (
                            n.clone(),
                            t.as_ref().map_or(Ty::Unknown, |t| Ty::named(&t.name)),
                        )
                    })
                    .collect(),
            );
        }
        let t = self.catalogue.datatype(&name)?;
        (t.kind == TypeKind::Record).then(|| {
            t.components
                .iter()
                .map(|c| (c.name.clone(), Ty::named(&c.ty)))
                .collect()
        })
    }

    /// [`Types::components`], shared and remembered per named type.
    pub fn components_shared(&self, ty: &Ty) -> Option<Components> {
        let Ty::Named(name) = ty else {
            return self.components(ty).map(Rc::from);
        };
        if let Some(found) = self.memo.borrow().components.get(name.as_str()) {
            return found.clone();
        }
        let found = self.components(ty).map(Rc::from);
        self.memo
            .borrow_mut()
            .components
            .insert(name.clone(), found.clone());
        found
    }

    /// `self.assignable(ty, &Ty::named(value))`, remembered per named type:
    /// may a literal of type `value` (`num`, `string`, `bool`) stand where
    /// `ty` is expected?
    pub fn accepts(&self, ty: &Ty, value: &'static str) -> bool {
        let slot = match value {
            "num" => 0,
            "string" => 1,
            _ => 2,
        };
        let Ty::Named(name) = ty else {
            return self.assignable(ty, &Ty::named(value));
        };
        if let Some(found) = self.memo.borrow().accepts[slot].get(name.as_str()) {
            return *found;
        }
        let found = self.assignable(ty, &Ty::named(value));
        self.memo.borrow_mut().accepts[slot].insert(name.clone(), found);
        found
    }

    /// The type of component `name` of a record type.
    pub fn component(&self, ty: &Ty, name: &str) -> Option<Ty> {
        self.components(ty)?
            .into_iter()
            .find(|(n, _)| same(n, name))
            .map(|(_, t)| t)
    }

    /// Value, semi-value or non-value (user records are value types unless a
    /// component is not; unknown types count as value types).
    pub fn value_class(&self, ty: &Ty) -> ValueClass {
        self.class_of(ty.element())
    }

    /// [`Types::value_class`] of `ty` itself (an array is a value).
    fn class_of(&self, ty: &Ty) -> ValueClass {
        let Ty::Named(name) = self.base(ty) else {
            return ValueClass::Value;
        };
        if self.user(&name).is_some() {
            return ValueClass::Value;
        }
        self.catalogue
            .datatype(&name)
            .and_then(|t| t.value_class)
            .unwrap_or(ValueClass::Value)
    }

    fn is_numeric(&self, ty: &Ty) -> bool {
        match ty {
            Ty::Named(name) => self.info(name).numeric,
            _ => self.is_numeric_uncached(ty),
        }
    }

    fn is_numeric_uncached(&self, ty: &Ty) -> bool {
        let base = self.base(ty);
        base.is("num") || base.is("dnum")
    }

    /// Is this a signal type, whose value reads as a number?
    pub fn is_signal(&self, ty: &Ty) -> bool {
        match ty {
            Ty::Named(name) => self.info(name).signal,
            _ => self.is_signal_uncached(ty),
        }
    }

    /// The semi-value types of the catalogue (the signals) read as numbers.
    fn is_signal_uncached(&self, ty: &Ty) -> bool {
        self.class_of(ty) == ValueClass::SemiValue
    }

    /// What the predicates above say of a named type, remembered per name
    /// as spelt (the checker asks them of the same few types all the time).
    fn info(&self, name: &str) -> Info {
        if let Some(info) = self.memo.borrow().info.get(name) {
            return *info;
        }
        let ty = Ty::named(name);
        let base = self.base(&ty);
        let base_name = match &base {
            Ty::Named(n) => fold(n),
            _ => String::new(),
        };
        let info = {
            let mut memo = self.memo.borrow_mut();
            let next = u32::try_from(memo.bases.len()).unwrap_or(u32::MAX);
            let base_id = *memo.bases.entry(base_name).or_insert(next);
            drop(memo);
            Info {
                exists: self.exists_uncached(name),
                opaque: matches!(base, Ty::Unknown),
                numeric: self.is_numeric_uncached(&ty),
                signal: self.is_signal_uncached(&ty),
                boolean: base.is("bool"),
                base_id,
                base_numeric: self.is_numeric_uncached(&base),
                base_signal: self.is_signal_uncached(&base),
            }
        };
        self.memo.borrow_mut().info.insert(name.to_owned(), info);
        info
    }

    /// The type a value of `ty` has when read in an expression: signals read
    /// as numbers, everything else as itself.
    pub fn value_type(&self, ty: &Ty) -> Ty {
        if self.is_signal(ty) {
            Ty::num()
        } else {
            ty.clone()
        }
    }

    /// May a value of this type stand where a number is read? Unknown types
    /// (unresolved type names included) may stand anywhere.
    pub fn is_num_like(&self, ty: &Ty) -> bool {
        ty.is_unknown() || !self.is_known(ty) || self.is_numeric(ty) || self.is_signal(ty)
    }

    /// May a value of this type stand where a bool is read?
    pub fn is_bool(&self, ty: &Ty) -> bool {
        match ty {
            Ty::Named(name) => {
                let info = self.info(name);
                info.boolean || !info.exists
            }
            _ => ty.is_unknown() || !self.is_known(ty) || self.base(ty).is("bool"),
        }
    }

    /// May a value of type `value` be stored where `target` is expected?
    /// Aliases are their base type; `num` and `dnum` convert into each other;
    /// a signal reads as a number.
    pub fn assignable(&self, target: &Ty, value: &Ty) -> bool {
        if !self.is_known(target) || !self.is_known(value) {
            return true;
        }
        match (target, value) {
            (Ty::Array(t, n), Ty::Array(v, m)) => n == m && self.assignable(t, v),
            (Ty::Array(..), _) | (_, Ty::Array(..)) => false,
            (Ty::Named(t), Ty::Named(v)) => {
                // As `base(target) == base(value)`, or the base of the
                // target numeric and that of the value numeric or a signal.
                let (t, v) = (self.info(t), self.info(v));
                t.base_id == v.base_id || (t.base_numeric && (v.base_numeric || v.base_signal))
            }
            _ => {
                let (t, v) = (self.base(target), self.base(value));
                t == v || (self.is_numeric(&t) && (self.is_numeric(&v) || self.is_signal(&v)))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aliases_are_their_base_type() {
        let types = Types::new([], crate::catalogue::base());
        assert!(types.assignable(&Ty::named("errnum"), &Ty::num()));
        assert!(types.assignable(&Ty::num(), &Ty::named("ERRNUM")));
        assert!(!types.assignable(&Ty::string(), &Ty::num()));
        assert!(types.assignable(&Ty::named("dnum"), &Ty::num()));
        assert!(types.assignable(&Ty::num(), &Ty::named("signaldi")));
        assert!(!types.assignable(&Ty::num().array(1), &Ty::num()));
    }

    #[test]
    fn records_have_components() {
        let types = Types::new([], crate::catalogue::base());
        let pos = types.components(&Ty::named("pos")).unwrap_or_default();
        let names: Vec<_> = pos.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["x", "y", "z"]);
        assert_eq!(
            types.component(&Ty::named("robtarget"), "TRANS"),
            Some(Ty::named("pos"))
        );
    }

    #[test]
    fn array_types_display_as_rapid_writes_parameters() {
        assert_eq!(Ty::num().array(2).to_string(), "num{*,*}");
    }
}
