//! The pure functions of RAPID: one implementation per pure function of the
//! catalogue, registered by its catalogue name. Parameter names, modes,
//! optional, switch and `|` groups and types come from the catalogue entry
//! (through [`Env::catalogue`]), which binds the arguments; an
//! implementation only reads them by name.

mod args;
mod bits;
mod frames;
mod math;
mod strings;
#[cfg(test)]
mod tests;

use crate::env::Env;
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::Ctx;
use crate::expr::Arg;
use crate::value::Value;

pub(crate) use args::Args;

/// An implementation: the result from the bound arguments. Those that
/// evaluate further (`StrToVal`) or count work get the context and the
/// environment.
#[derive(Clone, Copy)]
pub(crate) enum Impl {
    Pure(fn(&Args<'_>) -> Result<Value, EvalError>),
    Ctx(fn(&Args<'_>, &mut Ctx, &dyn Env) -> Result<Value, EvalError>),
}

use Impl::{Ctx as C, Pure as P};

/// Every implementation, by catalogue name (the manual's spelling).
const REGISTRY: &[(&str, Impl)] = &[
    ("Abs", P(math::abs)),
    ("AbsDnum", P(math::abs_dnum)),
    ("ACos", P(math::acos)),
    ("ASin", P(math::asin)),
    ("ATan", P(math::atan)),
    ("ATan2", P(math::atan2)),
    ("BitAnd", P(bits::bit_and)),
    ("BitCheck", P(bits::bit_check)),
    ("BitLSh", P(bits::bit_lsh)),
    ("BitNeg", P(bits::bit_neg)),
    ("BitOr", P(bits::bit_or)),
    ("BitRSh", P(bits::bit_rsh)),
    ("BitXOr", P(bits::bit_xor)),
    ("ByteToStr", P(strings::byte_to_str)),
    ("Cos", P(math::cos)),
    ("DecToHex", P(strings::dec_to_hex)),
    ("DefAccFrame", P(frames::def_acc_frame)),
    ("DefDFrame", P(frames::def_dframe)),
    ("DefFrame", P(frames::def_frame)),
    ("Dim", P(math::dim)),
    ("Distance", P(frames::distance)),
    ("DnumToNum", P(math::dnum_to_num)),
    ("DnumToStr", P(math::dnum_to_str)),
    ("DotProd", P(frames::dot_prod)),
    ("EulerZYX", P(frames::euler_zyx)),
    ("Exp", P(math::exp)),
    ("HexToDec", P(strings::hex_to_dec)),
    ("MirPos", P(frames::mir_pos)),
    ("NOrient", P(frames::norient)),
    ("NumToDnum", P(math::num_to_dnum)),
    ("NumToStr", P(math::num_to_str)),
    ("Offs", P(frames::offs)),
    ("OrientZYX", P(frames::orient_zyx)),
    ("PoseInv", P(frames::pose_inv)),
    ("PoseMult", P(frames::pose_mult)),
    ("PoseVect", P(frames::pose_vect)),
    ("Pow", P(math::pow)),
    ("RelTool", P(frames::rel_tool)),
    ("Round", P(math::round)),
    ("RoundDnum", P(math::round_dnum)),
    ("Sin", P(math::sin)),
    ("Sqrt", P(math::sqrt)),
    ("SqrtDnum", P(math::sqrt_dnum)),
    ("StrDigCalc", P(strings::str_dig_calc)),
    ("StrDigCmp", P(strings::str_dig_cmp)),
    ("StrFind", C(strings::str_find)),
    ("StrLen", P(strings::str_len)),
    ("StrMap", P(strings::str_map)),
    ("StrMatch", C(strings::str_match)),
    ("StrMemb", C(strings::str_memb)),
    ("StrOrder", P(strings::str_order)),
    ("StrPart", P(strings::str_part)),
    ("StrToByte", P(strings::str_to_byte)),
    ("StrToVal", C(strings::str_to_val)),
    ("Tan", P(math::tan)),
    ("Trunc", P(math::trunc)),
    ("TruncDnum", P(math::trunc_dnum)),
    ("ValToStr", P(strings::val_to_str)),
    ("VectMagn", P(frames::vect_magn)),
];

const fn names<const N: usize>() -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < N {
        out[i] = REGISTRY[i].0;
        i += 1;
    }
    out
}

/// The names of every function the evaluator implements, as the catalogue
/// spells them (the names of the registry).
pub const FUNCTIONS: &[&str] = &names::<{ REGISTRY.len() }>();

/// The implementation of `name` (case-insensitive).
fn implementation(name: &str) -> Option<Impl> {
    static SORTED: std::sync::OnceLock<Vec<(String, Impl)>> = std::sync::OnceLock::new();
    let sorted = SORTED.get_or_init(|| {
        let mut v: Vec<(String, Impl)> = REGISTRY
            .iter()
            .map(|(n, f)| (n.to_ascii_lowercase(), *f))
            .collect();
        v.sort_by(|a, b| a.0.cmp(&b.0));
        v
    });
    let lower = |b: &u8| b.to_ascii_lowercase();
    sorted
        .binary_search_by(|(f, _)| f.bytes().cmp(name.as_bytes().iter().map(lower)))
        .ok()
        .and_then(|i| sorted.get(i))
        .map(|(_, f)| *f)
}

/// Whether the evaluator implements the function `name` (case-insensitive).
pub fn is_function(name: &str) -> bool {
    implementation(name).is_some()
}

#[inline(never)]
/// `Dim` of a `VAR` or `PERS` array: its sizes are its declaration's,
/// known before the program runs though its values are not. `None` when
/// the call is not that (another function, an expression, a size that is
/// not known), to be evaluated as any call.
fn declared_dim(
    ctx: &mut Ctx,
    name: &str,
    args: &[Arg],
    env: &dyn Env,
) -> Option<Result<Value, EvalError>> {
    if !name.eq_ignore_ascii_case("Dim") {
        return None;
    }
    let named = |p: &str| {
        args.iter()
            .find(|a| a.name.as_deref().is_some_and(|n| n.eq_ignore_ascii_case(p)))
    };
    let mut positional = args.iter().filter(|a| a.name.is_none());
    let array = named("ArrPar").or_else(|| positional.next())?;
    let dim_no = named("DimNo").or_else(|| positional.next())?;
    let Some(crate::Expr::Name(array)) = &array.value else {
        return None;
    };
    let crate::env::Lookup::Variable { ty, .. } = env.lookup(array) else {
        return None;
    };
    if ty.dims.is_empty() {
        return None;
    }
    let d = match ctx.eval(
        dim_no.value.as_ref()?,
        Some(&crate::Type::named("num")),
        env,
    ) {
        Ok(v) => v.as_f64()?,
        Err(e) => return Some(Err(e)),
    };
    if d.fract() != 0.0 || d < 1.0 || d > ty.dims.len() as f64 {
        return Some(err(
            ErrorCode::IllDim,
            format!(
                "Dim: the array has no dimension {}",
                crate::value::format_g(d, 6)
            ),
        ));
    }
    match ty.dims[d as usize - 1] {
        0 => None,
        size => Some(Ok(Value::Num(size as f32))),
    }
}

pub(crate) fn call(
    ctx: &mut Ctx,
    name: &str,
    args: &[Arg],
    env: &dyn Env,
) -> Result<Value, EvalError> {
    let unknown = || {
        err(
            ErrorCode::UnknownFunction,
            format!("`{name}` is not a pure function the evaluator knows"),
        )
    };
    let Some(f) = implementation(name) else {
        return unknown();
    };
    let Some(routine) = env.catalogue().function(name) else {
        return unknown();
    };
    if let Some(size) = declared_dim(ctx, name, args, env) {
        return size;
    }
    let a = args::bind(ctx, name, routine, args, env)?;
    match f {
        Impl::Pure(f) => f(&a),
        Impl::Ctx(f) => f(&a, ctx, env),
    }
}
