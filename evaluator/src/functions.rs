//! The pure functions of RAPID.

use nalgebra::{Isometry3, Vector3};

use crate::env::{Env, Lookup};
use crate::error::{ErrorCode, EvalError, err};
use crate::eval::{Ctx, check_len, dnum_result, num_result, orient_of};
use crate::expr::{Arg, Expr, Type};
use crate::geometry as g;
use crate::value::{Value, format_g};

/// The names of every function the evaluator implements, as the manual
/// spells them.
pub const FUNCTIONS: &[&str] = &[
    "Abs",
    "AbsDnum",
    "ACos",
    "ASin",
    "ATan",
    "ATan2",
    "BitAnd",
    "BitCheck",
    "BitLSh",
    "BitNeg",
    "BitOr",
    "BitRSh",
    "BitXOr",
    "ByteToStr",
    "Cos",
    "DecToHex",
    "DefAccFrame",
    "DefDFrame",
    "DefFrame",
    "Dim",
    "Distance",
    "DnumToNum",
    "DnumToStr",
    "DotProd",
    "EulerZYX",
    "Exp",
    "HexToDec",
    "MirPos",
    "NOrient",
    "NumToDnum",
    "NumToStr",
    "Offs",
    "OrientZYX",
    "PoseInv",
    "PoseMult",
    "PoseVect",
    "Pow",
    "RelTool",
    "Round",
    "RoundDnum",
    "Sin",
    "Sqrt",
    "SqrtDnum",
    "StrDigCalc",
    "StrDigCmp",
    "StrFind",
    "StrLen",
    "StrMap",
    "StrMatch",
    "StrMemb",
    "StrOrder",
    "StrPart",
    "StrToByte",
    "StrToVal",
    "Tan",
    "Trunc",
    "TruncDnum",
    "ValToStr",
    "VectMagn",
];

/// Whether the evaluator implements the function `name` (case-insensitive).
pub fn is_function(name: &str) -> bool {
    static SORTED: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();
    let sorted = SORTED.get_or_init(|| {
        let mut v: Vec<String> = FUNCTIONS.iter().map(|f| f.to_ascii_lowercase()).collect();
        v.sort();
        v
    });
    let lower = |b: &u8| b.to_ascii_lowercase();
    sorted
        .binary_search_by(|f| f.bytes().cmp(name.as_bytes().iter().map(lower)))
        .is_ok()
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum K {
    /// Required, evaluated.
    Req,
    /// Optional `\Name:=value`.
    Opt,
    /// Switch `\Name`.
    Sw,
    /// Required reference (a data object, not evaluated).
    Ref,
}

struct P {
    name: &'static str,
    k: K,
    ty: &'static str,
    /// Parameters with the same non-zero group exclude each other.
    group: u8,
}

const fn req(name: &'static str, ty: &'static str) -> P {
    P {
        name,
        k: K::Req,
        ty,
        group: 0,
    }
}
const fn opt(name: &'static str, ty: &'static str) -> P {
    P {
        name,
        k: K::Opt,
        ty,
        group: 0,
    }
}
const fn sw(name: &'static str, group: u8) -> P {
    P {
        name,
        k: K::Sw,
        ty: "switch",
        group,
    }
}
const fn rf(name: &'static str) -> P {
    P {
        name,
        k: K::Ref,
        ty: "any",
        group: 0,
    }
}

const BYTE_FORMATS: [P; 4] = [sw("Hex", 1), sw("Okt", 1), sw("Bin", 1), sw("Char", 1)];

fn signature(lower: &str) -> Option<&'static [P]> {
    static ONE_NUM_INPUT: [P; 1] = [req("Input", "num")];
    static ONE_VALUE: [P; 1] = [req("Value", "num")];
    static ANGLE: [P; 1] = [req("Angle", "num")];
    static ATAN2: [P; 2] = [req("Y", "num"), req("X", "num")];
    static EXP: [P; 1] = [req("Exponent", "num")];
    static POW: [P; 2] = [req("Base", "num"), req("Exponent", "num")];
    static ROUND: [P; 2] = [req("Val", "num"), opt("Dec", "num")];
    static STRFIND: [P; 4] = [
        req("Str", "string"),
        req("ChPos", "num"),
        req("Set", "string"),
        sw("NotInSet", 0),
    ];
    static STRLEN: [P; 1] = [req("Str", "string")];
    static STRMAP: [P; 3] = [
        req("Str", "string"),
        req("FromMap", "string"),
        req("ToMap", "string"),
    ];
    static STRMATCH: [P; 3] = [
        req("Str", "string"),
        req("ChPos", "num"),
        req("Pattern", "string"),
    ];
    static STRMEMB: [P; 3] = [
        req("Str", "string"),
        req("ChPos", "num"),
        req("Set", "string"),
    ];
    static STRORDER: [P; 3] = [
        req("Str1", "string"),
        req("Str2", "string"),
        req("Order", "string"),
    ];
    static STRPART: [P; 3] = [req("Str", "string"), req("ChPos", "num"), req("Len", "num")];
    static BYTETOSTR: [P; 5] = {
        let [a, b, c, d] = BYTE_FORMATS;
        [req("BitData", "byte"), a, b, c, d]
    };
    static STRTOBYTE: [P; 5] = {
        let [a, b, c, d] = BYTE_FORMATS;
        [req("ConStr", "string"), a, b, c, d]
    };
    static NUMTOSTR: [P; 3] = [req("Val", "num"), req("Dec", "num"), sw("Exp", 0)];
    static STRTOVAL: [P; 2] = [req("Str", "string"), rf("Val")];
    static VALTOSTR: [P; 1] = [req("Val", "any")];
    static TWO_POINTS: [P; 2] = [req("Point1", "pos"), req("Point2", "pos")];
    static TWO_VECTORS: [P; 2] = [req("Vector1", "pos"), req("Vector2", "pos")];
    static VECTMAGN: [P; 1] = [req("Vector", "pos")];
    static POSEINV: [P; 1] = [req("Pose", "pose")];
    static POSEMULT: [P; 2] = [req("Pose1", "pose"), req("Pose2", "pose")];
    static POSEVECT: [P; 2] = [req("Pose", "pose"), req("Pos", "pos")];
    static ORIENTZYX: [P; 3] = [
        req("ZAngle", "num"),
        req("YAngle", "num"),
        req("XAngle", "num"),
    ];
    static EULERZYX: [P; 4] = [
        sw("X", 1),
        sw("Y", 1),
        sw("Z", 1),
        req("Rotation", "orient"),
    ];
    static NORIENT: [P; 1] = [req("Rotation", "orient")];
    static OFFS: [P; 4] = [
        req("Point", "robtarget"),
        req("XOffset", "num"),
        req("YOffset", "num"),
        req("ZOffset", "num"),
    ];
    static RELTOOL: [P; 7] = [
        req("Point", "robtarget"),
        req("Dx", "num"),
        req("Dy", "num"),
        req("Dz", "num"),
        opt("Rx", "num"),
        opt("Ry", "num"),
        opt("Rz", "num"),
    ];
    static MIRPOS: [P; 4] = [
        req("Point", "robtarget"),
        req("MirPlane", "wobjdata"),
        opt("WObj", "wobjdata"),
        sw("MirY", 0),
    ];
    static DEFFRAME: [P; 4] = [
        req("NewP1", "robtarget"),
        req("NewP2", "robtarget"),
        req("NewP3", "robtarget"),
        opt("Origin", "num"),
    ];
    static DEFDFRAME: [P; 6] = [
        req("OldP1", "robtarget"),
        req("OldP2", "robtarget"),
        req("OldP3", "robtarget"),
        req("NewP1", "robtarget"),
        req("NewP2", "robtarget"),
        req("NewP3", "robtarget"),
    ];
    static DEFACCFRAME: [P; 5] = [
        req("TargetListOne", "robtarget[]"),
        req("TargetListTwo", "robtarget[]"),
        req("TargetsInList", "num"),
        rf("MaxErr"),
        rf("MeanErr"),
    ];
    static DIM: [P; 2] = [req("ArrPar", "any"), req("DimNo", "num")];
    static NUMTODNUM: [P; 1] = [req("Value", "num")];
    static DNUMTONUM: [P; 2] = [req("Value", "dnum"), sw("Integer", 0)];
    static DNUM_VALUE: [P; 1] = [req("Value", "dnum")];
    static ROUNDDNUM: [P; 2] = [req("Val", "dnum"), opt("Dec", "num")];
    static DNUMTOSTR: [P; 3] = [req("Val", "dnum"), req("Dec", "num"), sw("Exp", 0)];
    static BIT2: [P; 2] = [req("BitData1", "byte"), req("BitData2", "byte")];
    static BIT1: [P; 1] = [req("BitData1", "byte")];
    static BITSHIFT: [P; 2] = [req("BitData", "byte"), req("ShiftSteps", "num")];
    static BITCHECK: [P; 2] = [req("BitData", "byte"), req("BitPos", "num")];
    static STRDIGCALC: [P; 3] = [
        req("StrDig1", "string"),
        req("Operation", "opcalc"),
        req("StrDig2", "string"),
    ];
    static ONE_STR: [P; 1] = [req("Str", "string")];
    static STRDIGCMP: [P; 3] = [
        req("StrDig1", "string"),
        req("Relation", "opnum"),
        req("StrDig2", "string"),
    ];
    Some(match lower {
        "abs" => &ONE_NUM_INPUT,
        "absdnum" | "sqrtdnum" => &DNUM_VALUE,
        "rounddnum" | "truncdnum" => &ROUNDDNUM,
        "dnumtostr" => &DNUMTOSTR,
        "bitand" | "bitor" | "bitxor" => &BIT2,
        "bitneg" => &BIT1,
        "bitlsh" | "bitrsh" => &BITSHIFT,
        "bitcheck" => &BITCHECK,
        "strdigcalc" => &STRDIGCALC,
        "acos" | "asin" | "atan" | "sqrt" => &ONE_VALUE,
        "cos" | "sin" | "tan" => &ANGLE,
        "atan2" => &ATAN2,
        "exp" => &EXP,
        "pow" => &POW,
        "round" | "trunc" => &ROUND,
        "strfind" => &STRFIND,
        "strlen" => &STRLEN,
        "strmap" => &STRMAP,
        "strmatch" => &STRMATCH,
        "strmemb" => &STRMEMB,
        "strorder" => &STRORDER,
        "strpart" => &STRPART,
        "bytetostr" => &BYTETOSTR,
        "strtobyte" => &STRTOBYTE,
        "numtostr" => &NUMTOSTR,
        "strtoval" => &STRTOVAL,
        "valtostr" => &VALTOSTR,
        "distance" => &TWO_POINTS,
        "dotprod" => &TWO_VECTORS,
        "vectmagn" => &VECTMAGN,
        "poseinv" => &POSEINV,
        "posemult" => &POSEMULT,
        "posevect" => &POSEVECT,
        "orientzyx" => &ORIENTZYX,
        "eulerzyx" => &EULERZYX,
        "norient" => &NORIENT,
        "offs" => &OFFS,
        "reltool" => &RELTOOL,
        "mirpos" => &MIRPOS,
        "defframe" => &DEFFRAME,
        "defdframe" => &DEFDFRAME,
        "defaccframe" => &DEFACCFRAME,
        "dim" => &DIM,
        "numtodnum" => &NUMTODNUM,
        "dnumtonum" => &DNUMTONUM,
        "dectohex" | "hextodec" => &ONE_STR,
        "strdigcmp" => &STRDIGCMP,
        _ => return None,
    })
}

enum Slot<'a> {
    Empty,
    Val(Value),
    Sw,
    Ref(&'a Expr),
}

struct Args<'a> {
    func: &'a str,
    params: &'static [P],
    slots: Vec<Slot<'a>>,
}

impl Args<'_> {
    fn idx(&self, name: &str) -> usize {
        self.params
            .iter()
            .position(|p| p.name == name)
            .unwrap_or(usize::MAX)
    }
    fn get(&self, name: &str) -> Option<&Value> {
        match self.slots.get(self.idx(name)) {
            Some(Slot::Val(v)) => Some(v),
            _ => None,
        }
    }
    fn val(&self, name: &str) -> Result<&Value, EvalError> {
        self.get(name).ok_or_else(|| {
            EvalError::new(
                ErrorCode::BadArguments,
                format!("{}: argument {name} is missing", self.func),
            )
        })
    }
    fn num(&self, name: &str) -> Result<f64, EvalError> {
        match self.val(name)? {
            v @ (Value::Num(_) | Value::Dnum(_)) => Ok(v.as_f64().unwrap_or(0.0)),
            _ => err(
                ErrorCode::TypeMismatch,
                format!("{}: argument {name} must be a number", self.func),
            ),
        }
    }
    fn opt_num(&self, name: &str) -> Result<Option<f64>, EvalError> {
        match self.get(name) {
            Some(_) => self.num(name).map(Some),
            None => Ok(None),
        }
    }
    fn str(&self, name: &str) -> Result<&str, EvalError> {
        match self.val(name)? {
            Value::Str(s) => Ok(s),
            _ => err(
                ErrorCode::TypeMismatch,
                format!("{}: argument {name} must be a string", self.func),
            ),
        }
    }
    fn sw(&self, name: &str) -> bool {
        matches!(self.slots.get(self.idx(name)), Some(Slot::Sw))
    }
    fn reference(&self, name: &str) -> Option<&Expr> {
        match self.slots.get(self.idx(name)) {
            Some(Slot::Ref(e)) => Some(e),
            _ => None,
        }
    }
}

fn bad<T>(func: &str, msg: impl std::fmt::Display) -> Result<T, EvalError> {
    err(ErrorCode::BadArguments, format!("{func}: {msg}"))
}

fn bind<'a>(
    ctx: &mut Ctx,
    func: &'a str,
    params: &'static [P],
    args: &'a [Arg],
    env: &dyn Env,
) -> Result<Args<'a>, EvalError> {
    let mut slots: Vec<Slot<'a>> = params.iter().map(|_| Slot::Empty).collect();
    let mut pending: Vec<Option<&'a Expr>> = params.iter().map(|_| None).collect();
    let mut bound = vec![false; params.len()];
    for arg in args {
        let i = match &arg.name {
            Some(n) => match params.iter().position(|p| p.name.eq_ignore_ascii_case(n)) {
                Some(i) => i,
                None => return bad(func, format_args!("there is no parameter {n}")),
            },
            None => match params
                .iter()
                .enumerate()
                .position(|(i, p)| matches!(p.k, K::Req | K::Ref) && !bound[i])
            {
                Some(i) => i,
                None => return bad(func, "too many arguments"),
            },
        };
        let p = &params[i];
        if bound[i] {
            return bad(func, format_args!("argument {} is given twice", p.name));
        }
        bound[i] = true;
        match (p.k, &arg.value) {
            (K::Sw, None) => slots[i] = Slot::Sw,
            (K::Sw, Some(_)) => {
                return bad(
                    func,
                    format_args!("\\{} is a switch and takes no value", p.name),
                );
            }
            (_, None) => return bad(func, format_args!("argument {} needs a value", p.name)),
            (K::Ref, Some(e)) => slots[i] = Slot::Ref(e),
            (_, Some(e)) => pending[i] = Some(e),
        }
    }
    for (i, p) in params.iter().enumerate() {
        if matches!(p.k, K::Req | K::Ref) && !bound[i] {
            return bad(func, format_args!("argument {} is missing", p.name));
        }
        if p.group != 0
            && bound[i]
            && params
                .iter()
                .enumerate()
                .any(|(j, q)| j > i && q.group == p.group && bound[j])
        {
            return bad(func, "mutually exclusive arguments are given together");
        }
    }
    for (i, p) in params.iter().enumerate() {
        if let Some(e) = pending[i] {
            let ty = match p.ty {
                "any" => None,
                t => match t.strip_suffix("[]") {
                    Some(elem) => Some(Type::array(elem, vec![0])),
                    None => Some(Type::named(t)),
                },
            };
            slots[i] = Slot::Val(ctx.eval(e, ty.as_ref(), env)?);
        }
    }
    Ok(Args {
        func,
        params,
        slots,
    })
}

#[inline(never)]
pub(crate) fn call(
    ctx: &mut Ctx,
    name: &str,
    args: &[Arg],
    env: &dyn Env,
) -> Result<Value, EvalError> {
    let lower = name.to_ascii_lowercase();
    let Some(params) = signature(&lower) else {
        return err(
            ErrorCode::UnknownFunction,
            format!("`{name}` is not a pure function the evaluator knows"),
        );
    };
    let a = bind(ctx, name, params, args, env)?;
    match lower.as_str() {
        "abs" => num_result(a.num("Input")?.abs()),
        "absdnum" => dnum_result(a.num("Value")?.abs()),
        "sqrtdnum" => {
            let x = a.num("Value")?;
            if x < 0.0 {
                return err(ErrorCode::ArgValErr, "SqrtDnum: the argument is negative");
            }
            dnum_result(x.sqrt())
        }
        "rounddnum" | "truncdnum" => {
            let dec = decimals(&a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
            let x = a.num("Val")?;
            dnum_result(if lower == "rounddnum" {
                round_dec(x, dec)
            } else {
                trunc_dec(x, dec)
            })
        }
        "bitand" | "bitor" | "bitxor" => {
            let x = byte_arg(&a, "BitData1")?;
            let y = byte_arg(&a, "BitData2")?;
            Ok(Value::Num(f32::from(match lower.as_str() {
                "bitand" => x & y,
                "bitor" => x | y,
                _ => x ^ y,
            })))
        }
        "bitneg" => Ok(Value::Num(f32::from(!byte_arg(&a, "BitData1")?))),
        "bitlsh" | "bitrsh" => {
            let x = byte_arg(&a, "BitData")?;
            let n = a.num("ShiftSteps")?;
            if n.fract() != 0.0 || !(0.0..=8.0).contains(&n) {
                return err(
                    ErrorCode::ArgValErr,
                    format!("{name}: ShiftSteps must be a whole number from 0 to 8"),
                );
            }
            let v = u32::from(x);
            let r = if lower == "bitlsh" {
                v << n as u32
            } else {
                v >> n as u32
            };
            Ok(Value::Num((r & 0xff) as f32))
        }
        "bitcheck" => {
            let x = byte_arg(&a, "BitData")?;
            let p = a.num("BitPos")?;
            if p.fract() != 0.0 || !(1.0..=8.0).contains(&p) {
                return err(
                    ErrorCode::ArgValErr,
                    "BitCheck: BitPos must be a whole number from 1 to 8",
                );
            }
            Ok(Value::Bool(x & (1 << (p as u32 - 1)) != 0))
        }
        "dnumtostr" => {
            let dec = decimals(&a, "Dec", a.num("Dec")?)?;
            let x = a.num("Val")?;
            let s = if a.sw("Exp") {
                exp_format(x, dec)
            } else {
                format!("{:.*}", dec as usize, round_dec(x, dec))
            };
            check_len(s)
        }
        "strdigcalc" => {
            let n1 = dig_value(name, a.str("StrDig1")?)?;
            let n2 = dig_value(name, a.str("StrDig2")?)?;
            let op = a.num("Operation")?;
            let op = if op.fract() == 0.0 { op as i64 } else { 0 };
            let r = match op {
                1 => n1.checked_add(n2),
                2 => n1.checked_sub(n2),
                3 => n1.checked_mul(n2),
                4 | 5 if n2 == 0 => {
                    return err(ErrorCode::DivZero, "StrDigCalc: division by zero");
                }
                4 => Some(n1 / n2),
                5 => Some(n1 % n2),
                _ => {
                    return err(
                        ErrorCode::ArgValErr,
                        "StrDigCalc: the operation must be OpAdd, OpSub, OpMult, OpDiv or OpMod",
                    );
                }
            };
            match r {
                Some(v) if v <= 4_294_967_295 => Ok(Value::Str(v.to_string())),
                _ => err(
                    ErrorCode::MaxIntVal,
                    "StrDigCalc: the result is outside 0 to 4294967295",
                ),
            }
        }

        "acos" | "asin" => {
            let x = a.num("Value")?;
            if !(-1.0..=1.0).contains(&x) {
                return err(
                    ErrorCode::ArgValErr,
                    format!("{name}: the argument {} is outside [-1, 1]", format_g(x, 6)),
                );
            }
            num_result(if lower == "acos" { x.acos() } else { x.asin() }.to_degrees())
        }
        "atan" => num_result(a.num("Value")?.atan().to_degrees()),
        "atan2" => num_result(a.num("Y")?.atan2(a.num("X")?).to_degrees()),
        "sin" => num_result(g::sin_deg(a.num("Angle")?)),
        "cos" => num_result(g::cos_deg(a.num("Angle")?)),
        "tan" => {
            let x = a.num("Angle")?;
            let c = g::cos_deg(x);
            if c == 0.0 {
                return err(
                    ErrorCode::NumLimit,
                    "Tan: the tangent of this angle is infinite",
                );
            }
            num_result(g::sin_deg(x) / c)
        }
        "exp" => num_result(a.num("Exponent")?.exp()),
        "pow" => {
            let (x, y) = (a.num("Base")?, a.num("Exponent")?);
            if x < 0.0 && y.fract() != 0.0 {
                return err(
                    ErrorCode::ArgValErr,
                    "Pow: a negative base needs an integer exponent",
                );
            }
            if x == 0.0 && y < 0.0 {
                return err(
                    ErrorCode::ArgValErr,
                    "Pow: zero cannot have a negative exponent",
                );
            }
            num_result(x.powf(y))
        }
        "sqrt" => {
            let x = a.num("Value")?;
            if x < 0.0 {
                return err(ErrorCode::ArgValErr, "Sqrt: the argument is negative");
            }
            num_result(x.sqrt())
        }
        "round" | "trunc" => {
            let dec = decimals(&a, "Dec", a.opt_num("Dec")?.unwrap_or(0.0))?;
            let x = decimal_of(a.val("Val")?);
            num_result(if lower == "round" {
                round_dec(x, dec)
            } else {
                trunc_dec(x, dec)
            })
        }
        "strfind" | "strmatch" | "strmemb" => {
            let s: Vec<char> = a.str("Str")?.chars().collect();
            let pos = char_pos(&a, s.len())?;
            ctx.step(s.len() as u64)?;
            match lower.as_str() {
                "strfind" => {
                    let set = a.str("Set")?;
                    let not = a.sw("NotInSet");
                    let found = s
                        .iter()
                        .enumerate()
                        .skip(pos - 1)
                        .find(|(_, c)| set.contains(**c) != not)
                        .map_or(s.len() + 1, |(i, _)| i + 1);
                    Ok(Value::Num(found as f32))
                }
                "strmatch" => {
                    let pat: Vec<char> = a.str("Pattern")?.chars().collect();
                    let found = (pos - 1..=s.len())
                        .find(|&i| s.get(i..i + pat.len()) == Some(&pat[..]))
                        .map_or(s.len() + 1, |i| i + 1);
                    Ok(Value::Num(found as f32))
                }
                _ => {
                    let set = a.str("Set")?;
                    Ok(Value::Bool(
                        s.get(pos - 1).is_some_and(|c| set.contains(*c)),
                    ))
                }
            }
        }
        "strlen" => Ok(Value::Num(a.str("Str")?.chars().count() as f32)),
        "strmap" => {
            let from: Vec<char> = a.str("FromMap")?.chars().collect();
            let to: Vec<char> = a.str("ToMap")?.chars().collect();
            let out: String = a
                .str("Str")?
                .chars()
                .map(|c| {
                    from.iter()
                        .position(|f| *f == c)
                        .and_then(|i| to.get(i).copied())
                        .unwrap_or(c)
                })
                .collect();
            check_len(out)
        }
        "strorder" => {
            let order: Vec<char> = a.str("Order")?.chars().collect();
            let rank = |c: char| {
                order
                    .iter()
                    .position(|o| *o == c)
                    .map_or(order.len() as u32 + c as u32, |i| i as u32)
            };
            let s1: Vec<u32> = a.str("Str1")?.chars().map(rank).collect();
            let s2: Vec<u32> = a.str("Str2")?.chars().map(rank).collect();
            Ok(Value::Bool(s1 <= s2))
        }
        "strpart" => {
            let s: Vec<char> = a.str("Str")?.chars().collect();
            let pos = char_pos(&a, s.len())?;
            let len = a.num("Len")?;
            if len.fract() != 0.0 {
                return err(
                    ErrorCode::NotIntVal,
                    "StrPart: the length must be an integer",
                );
            }
            if len < 0.0 || (pos - 1) as f64 + len > s.len() as f64 {
                return err(
                    ErrorCode::OutOfBnd,
                    format!(
                        "StrPart: {} characters from position {pos} go past the end of the string ({} characters)",
                        format_g(len, 6),
                        s.len()
                    ),
                );
            }
            Ok(Value::Str(
                s[pos - 1..pos - 1 + len as usize].iter().collect(),
            ))
        }
        "bytetostr" => {
            let b = byte_arg(&a, "BitData")?;
            Ok(Value::Str(if a.sw("Hex") {
                format!("{b:02X}")
            } else if a.sw("Okt") {
                format!("{b:03o}")
            } else if a.sw("Bin") {
                format!("{b:08b}")
            } else if a.sw("Char") {
                if b < 0x20 || (0x7f..0xa0).contains(&b) {
                    format!("\\{b:02X}")
                } else {
                    char::from(b).to_string()
                }
            } else {
                b.to_string()
            }))
        }
        "strtobyte" => {
            let s = a.str("ConStr")?;
            let parsed = if a.sw("Hex") {
                digits(s, 16, 2)
            } else if a.sw("Okt") {
                digits(s, 8, 3)
            } else if a.sw("Bin") {
                digits(s, 2, 8)
            } else if a.sw("Char") {
                let cs: Vec<char> = s.chars().collect();
                match cs.as_slice() {
                    [c] => Some(*c as u32),
                    ['\\', h1, h2] => match (h1.to_digit(16), h2.to_digit(16)) {
                        (Some(x), Some(y)) => Some(x * 16 + y),
                        _ => None,
                    },
                    _ => None,
                }
            } else {
                digits(s, 10, 3)
            };
            match parsed {
                Some(v) if v <= 255 => Ok(Value::Num(v as f32)),
                _ => err(
                    ErrorCode::ArgValErr,
                    format!(
                        "StrToByte: {} is not a valid byte in this format",
                        crate::value::quote_string(s)
                    ),
                ),
            }
        }
        "numtostr" => {
            let dec = decimals(&a, "Dec", a.num("Dec")?)?;
            let x = decimal_of(a.val("Val")?);
            let s = if a.sw("Exp") {
                exp_format(x, dec)
            } else {
                format!("{:.*}", dec as usize, round_dec(x, dec))
            };
            check_len(s)
        }
        "valtostr" => check_len(a.val("Val")?.to_string()),
        "strtoval" => str_to_val(ctx, &a, env),
        "distance" => {
            let d = g::vec_of(a.val("Point1")?)? - g::vec_of(a.val("Point2")?)?;
            num_result(d.norm())
        }
        "dotprod" => num_result(g::vec_of(a.val("Vector1")?)?.dot(&g::vec_of(a.val("Vector2")?)?)),
        "vectmagn" => num_result(g::vec_of(a.val("Vector")?)?.norm()),
        "poseinv" => g::pose_value(&g::iso_of(a.val("Pose")?)?.inverse(), false),
        "posemult" => {
            let p = g::iso_of(a.val("Pose1")?)? * g::iso_of(a.val("Pose2")?)?;
            g::pose_value(&p, false)
        }
        "posevect" => {
            let p = g::iso_of(a.val("Pose")?)?;
            let v = g::vec_of(a.val("Pos")?)?;
            g::pos_value(&p.transform_point(&v.into()).coords)
        }
        "orientzyx" => {
            let q = g::orient_zyx(a.num("ZAngle")?, a.num("YAngle")?, a.num("XAngle")?);
            g::orient_value(&q, true)
        }
        "eulerzyx" => {
            let q = g::unit_quat(orient_of(a.val("Rotation")?)?)?;
            let e = g::euler_zyx_deg([q.w, q.i, q.j, q.k]);
            let v = if a.sw("Z") {
                e[0]
            } else if a.sw("Y") {
                e[1]
            } else if a.sw("X") {
                e[2]
            } else {
                return err(
                    ErrorCode::ArgValErr,
                    "EulerZYX: one of \\X, \\Y or \\Z must be given",
                );
            };
            num_result(v)
        }
        "norient" => {
            let q = orient_of(a.val("Rotation")?)?;
            let qd = q.map(f64::from);
            let norm = qd.iter().map(|x| x * x).sum::<f64>().sqrt();
            let normerr = (norm - 1.0).abs();
            if !normerr.is_finite() || normerr > 0.1 {
                return err(
                    ErrorCode::IllQuat,
                    format!("NOrient: the orientation is too far from normalised (norm {norm:.6})"),
                );
            }
            if normerr <= 0.00001 {
                return Ok(Value::orient(q));
            }
            let mut out = [0f32; 4];
            for (o, x) in out.iter_mut().zip(qd) {
                *o = (x / norm) as f32;
            }
            Ok(Value::orient(out))
        }
        "offs" => {
            let p = a.val("Point")?;
            let t = g::vec_of(p.field("trans").unwrap_or(&Value::Bool(false)))?;
            let d = Vector3::new(a.num("XOffset")?, a.num("YOffset")?, a.num("ZOffset")?);
            g::with_frame(p, &(t + d), None)
        }
        "reltool" => {
            let p = a.val("Point")?;
            let frame = g::iso_of(p)?;
            let d = Vector3::new(a.num("Dx")?, a.num("Dy")?, a.num("Dz")?);
            let t = frame.translation.vector + frame.rotation * d;
            let (rx, ry, rz) = (a.opt_num("Rx")?, a.opt_num("Ry")?, a.opt_num("Rz")?);
            let rot = if rx.is_some() || ry.is_some() || rz.is_some() {
                let q = frame.rotation
                    * g::axis_quat(0, rx.unwrap_or(0.0))
                    * g::axis_quat(1, ry.unwrap_or(0.0))
                    * g::axis_quat(2, rz.unwrap_or(0.0));
                Some(g::orient_value(&q, false)?)
            } else {
                None
            };
            g::with_frame(p, &t, rot)
        }
        "mirpos" => {
            let p = a.val("Point")?;
            let mirror = wobj_frame(a.val("MirPlane")?)?;
            let wobj = match a.get("WObj") {
                Some(w) => wobj_frame(w)?,
                None => Isometry3::identity(),
            };
            let r = g::mir_pos(&g::iso_of(p)?, &mirror, &wobj, a.sw("MirY"))?;
            g::with_frame(
                p,
                &r.translation.vector,
                Some(g::orient_value(&r.rotation, true)?),
            )
        }
        "defframe" => {
            let p = |n: &str| -> Result<Vector3<f64>, EvalError> { trans_of(a.val(n)?) };
            let origin = a.opt_num("Origin")?.unwrap_or(1.0);
            let origin = if origin.fract() == 0.0 {
                origin as i64
            } else {
                1
            };
            let f = g::def_frame(&p("NewP1")?, &p("NewP2")?, &p("NewP3")?, origin)?;
            g::pose_value(&f, true)
        }
        "defdframe" => {
            let p = |n: &str| -> Result<Vector3<f64>, EvalError> { trans_of(a.val(n)?) };
            let f = g::def_dframe(
                [p("OldP1")?, p("OldP2")?, p("OldP3")?],
                [p("NewP1")?, p("NewP2")?, p("NewP3")?],
            )?;
            g::pose_value(&f, true)
        }
        "defaccframe" => {
            let n = a.num("TargetsInList")?;
            if n.fract() != 0.0 || !(3.0..=10.0).contains(&n) {
                return err(
                    ErrorCode::ArgValErr,
                    "DefAccFrame: the number of targets must be 3 to 10",
                );
            }
            let n = n as usize;
            let list = |name: &str| -> Result<Vec<Vector3<f64>>, EvalError> {
                match a.val(name)? {
                    Value::Array(items) if items.len() >= n => {
                        items.iter().take(n).map(trans_of).collect()
                    }
                    Value::Array(_) => err(
                        ErrorCode::OutOfBnd,
                        format!("DefAccFrame: {name} holds fewer than {n} targets"),
                    ),
                    _ => err(
                        ErrorCode::TypeMismatch,
                        format!("DefAccFrame: {name} must be an array of robtarget"),
                    ),
                }
            };
            let f = g::def_acc_frame(&list("TargetListOne")?, &list("TargetListTwo")?)?;
            g::pose_value(&f, true)
        }
        "dim" => {
            let d = a.num("DimNo")?;
            let mut v = a.val("ArrPar")?;
            if !matches!(v, Value::Array(_)) {
                return err(ErrorCode::TypeMismatch, "Dim: the argument is not an array");
            }
            if d.fract() != 0.0 || d < 1.0 {
                return err(ErrorCode::IllDim, "Dim: the dimension must be 1, 2 or 3");
            }
            let mut k = 1.0;
            loop {
                let Value::Array(items) = v else {
                    return err(
                        ErrorCode::IllDim,
                        format!("Dim: the array has no dimension {}", format_g(d, 6)),
                    );
                };
                if k == d {
                    return Ok(Value::Num(items.len() as f32));
                }
                match items.first() {
                    Some(first) => v = first,
                    None => {
                        return err(
                            ErrorCode::IllDim,
                            format!("Dim: the array has no dimension {}", format_g(d, 6)),
                        );
                    }
                }
                k += 1.0;
            }
        }
        "numtodnum" => dnum_result(a.num("Value")?),
        "dnumtonum" => {
            let x = a.num("Value")?;
            if a.sw("Integer") && (x.fract() != 0.0 || x.abs() > crate::eval::NUM_INT_MAX) {
                return err(
                    ErrorCode::ArgValErr,
                    "DnumToNum: the value is not an integer that num holds exactly",
                );
            }
            num_result(x)
        }
        "dectohex" => {
            let s = a.str("Str")?;
            match digits(s, 10, 20).map(u64::from).or_else(|| dec_u64(s)) {
                Some(v) => Ok(Value::Str(format!("{v:X}"))),
                None => err(
                    ErrorCode::ArgValErr,
                    "DecToHex: the string must hold only decimal digits",
                ),
            }
        }
        "hextodec" => {
            let s = a.str("Str")?;
            let ok = !s.is_empty() && s.len() <= 16 && s.chars().all(|c| c.is_ascii_hexdigit());
            match u64::from_str_radix(s, 16) {
                Ok(v) if ok => Ok(Value::Str(v.to_string())),
                _ => err(
                    ErrorCode::ArgValErr,
                    "HexToDec: the string must hold only hexadecimal digits",
                ),
            }
        }
        "strdigcmp" => {
            let n1 = dig_value(name, a.str("StrDig1")?)?;
            let n2 = dig_value(name, a.str("StrDig2")?)?;
            let rel = a.num("Relation")?;
            let rel = if rel.fract() == 0.0 { rel as i64 } else { 0 };
            Ok(Value::Bool(match rel {
                1 => n1 < n2,
                2 => n1 <= n2,
                3 => n1 == n2,
                4 => n1 != n2,
                5 => n1 >= n2,
                6 => n1 > n2,
                _ => {
                    return err(
                        ErrorCode::ArgValErr,
                        "StrDigCmp: the relation must be LT, LTEQ, EQ, NOTEQ, GTEQ or GT",
                    );
                }
            }))
        }
        _ => err(
            ErrorCode::UnknownFunction,
            format!("`{name}` is not implemented"),
        ),
    }
}

fn trans_of(v: &Value) -> Result<Vector3<f64>, EvalError> {
    match v.field("trans") {
        Some(t) => g::vec_of(t),
        None => err(ErrorCode::TypeMismatch, "expected a robtarget"),
    }
}

fn wobj_frame(w: &Value) -> Result<Isometry3<f64>, EvalError> {
    match (w.field("uframe"), w.field("oframe")) {
        (Some(u), Some(o)) => Ok(g::iso_of(u)? * g::iso_of(o)?),
        _ => err(ErrorCode::TypeMismatch, "expected a wobjdata"),
    }
}

fn dec_u64(s: &str) -> Option<u64> {
    if s.is_empty() || !s.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// A `stringdig` argument: decimal digits only, at most 4294967295.
fn dig_value(func: &str, s: &str) -> Result<u64, EvalError> {
    if s.is_empty() || !s.chars().all(|c| c.is_ascii_digit()) {
        return err(
            ErrorCode::NotIntVal,
            format!("{func}: the strings must hold only decimal digits"),
        );
    }
    let significant = s.trim_start_matches('0');
    match significant.parse::<u64>() {
        Ok(v) if significant.len() <= 10 && v <= 4_294_967_295 => Ok(v),
        _ if significant.is_empty() => Ok(0),
        _ => err(
            ErrorCode::MaxIntVal,
            format!("{func}: the value is larger than 4294967295"),
        ),
    }
}

/// A `byte` argument: a whole number from 0 to 255.
fn byte_arg(a: &Args<'_>, name: &str) -> Result<u8, EvalError> {
    let b = a.num(name)?;
    if b.fract() != 0.0 || !(0.0..=255.0).contains(&b) {
        return err(
            ErrorCode::ArgValErr,
            format!("{}: {} is not a byte (0 to 255)", a.func, format_g(b, 6)),
        );
    }
    Ok(b as u8)
}

/// Parses 1..=`max_len` digits of `radix`.
fn digits(s: &str, radix: u32, max_len: usize) -> Option<u32> {
    if s.is_empty() || s.chars().count() > max_len || !s.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    u32::from_str_radix(s, radix).ok()
}

/// A 1-based character position argument `ChPos`, checked against the
/// string length.
fn char_pos(a: &Args<'_>, len: usize) -> Result<usize, EvalError> {
    let p = a.num("ChPos")?;
    if p.fract() != 0.0 {
        return err(
            ErrorCode::NotIntVal,
            format!("{}: the position must be an integer", a.func),
        );
    }
    if p < 1.0 || p > len as f64 {
        return err(
            ErrorCode::OutOfBnd,
            format!(
                "{}: position {} is outside the string (1 to {len})",
                a.func,
                format_g(p, 6)
            ),
        );
    }
    Ok(p as usize)
}

/// A number-of-decimals argument: an integer from 0 to 15.
fn decimals(a: &Args<'_>, name: &str, d: f64) -> Result<i32, EvalError> {
    if d.fract() != 0.0 || !(0.0..=15.0).contains(&d) {
        return err(
            ErrorCode::ArgValErr,
            format!(
                "{}: {name} must be a whole number of decimals from 0 to 15, not {}",
                a.func,
                format_g(d, 6)
            ),
        );
    }
    Ok(d as i32)
}

/// The decimal number a value stands for: a num is taken as the shortest
/// decimal that reads back as the same single-precision value (0.7, not
/// 0.699999988), so rounding and truncation act on the digits the user
/// wrote.
fn decimal_of(v: &Value) -> f64 {
    match v {
        Value::Num(x) => x.to_string().parse().unwrap_or(f64::from(*x)),
        Value::Dnum(x) => *x,
        _ => 0.0,
    }
}

/// Rounds half away from zero to `dec` decimals.
fn round_dec(x: f64, dec: i32) -> f64 {
    let m = 10f64.powi(dec);
    let y = x * m;
    // A half written in decimal may be stored just below it (2.675 is
    // 2.67499999999999982236431605997495353221893310546875 in binary): it
    // rounds up, as the decimal says. Only a few units in the last place
    // count as such a half; a relative nudge of its own would move large
    // values by whole units (16777216e6 printed as 16777216000017).
    // (Past about 1e14 a unit in the last place is a sizeable part of one:
    // no nudge there.)
    let half = y.abs().fract();
    let tolerance = 8.0 * f64::EPSILON * y.abs();
    let r = if tolerance < 0.25 && (half - 0.5).abs() <= tolerance {
        (y.abs().trunc() + 1.0).copysign(y)
    } else {
        y.round()
    };
    r / m
}

/// Truncates towards zero to `dec` decimals.
fn trunc_dec(x: f64, dec: i32) -> f64 {
    let m = 10f64.powi(dec);
    let y = x * m;
    let r = y.round();
    if (y - r).abs() <= 1e-9 * r.abs().max(1.0) {
        r / m
    } else {
        y.trunc() / m
    }
}

/// `d.ddE+xx` with `dec` decimals.
fn exp_format(x: f64, dec: i32) -> String {
    let s = format!("{:.*E}", dec as usize, x);
    match s.split_once('E') {
        Some((m, e)) => {
            let e: i32 = e.parse().unwrap_or(0);
            let sign = if e < 0 { '-' } else { '+' };
            format!("{m}E{sign}{:02}", e.abs())
        }
        None => s,
    }
}

fn str_to_val(ctx: &mut Ctx, a: &Args<'_>, env: &dyn Env) -> Result<Value, EvalError> {
    let text = a.str("Str")?.to_string();
    let ty = match a.reference("Val") {
        Some(Expr::Name(n)) => match env.lookup(n) {
            Lookup::Constant { ty, .. } | Lookup::Variable { ty, .. } => ty,
            Lookup::Known { value } => match value.type_name() {
                Some(t) => Type::named(t),
                None => {
                    return err(
                        ErrorCode::Unsupported,
                        "StrToVal: the type of the target is not known",
                    );
                }
            },
            Lookup::Unknown => {
                return err(ErrorCode::UnknownName, format!("`{n}` is not known"));
            }
        },
        _ => {
            return err(
                ErrorCode::Unsupported,
                "StrToVal: the target must be a data object name",
            );
        }
    };
    let Some(expr) = crate::literal_value::parse(&text) else {
        return Ok(Value::Bool(false));
    };
    match ctx.eval(&expr, Some(&ty), env) {
        Ok(_) => Ok(Value::Bool(true)),
        Err(e) if matches!(e.code, ErrorCode::TooComplex | ErrorCode::TooDeep) => Err(e),
        Err(_) => Ok(Value::Bool(false)),
    }
}
