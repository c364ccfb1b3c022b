//! Constant values for hovers and inlay hints, from [`crate::consteval`].

pub(crate) use crate::consteval::{ConstValue, value_at, value_of_range};
