//! Accuracy modes: how exactly filled triangles compute their attributes, traded for time.
//!
//! A context reads `TESSERA_ACCURACY` once, when it is created; `tesseraSetAccuracy` changes
//! its mode for the draws that follow (a draw's primitives are set up in the mode current at
//! the draw). The modes change only filled triangles' attribute interpolation and dithering;
//! coverage (exact 64-bit edge functions over 24.8 fixed point) is the same in every mode,
//! as are lines, points, clears and every per-fragment operation.
//!
//! - [`Accuracy::Conformant`] (default): colors and varyings perspective-correct from f32
//!   planes of a/w and 1/w, window z linear; what the capi tests compare with Mesa.
//! - [`Accuracy::Fast`]: colors and varyings interpolated linearly in window space (affine,
//!   no divide per fragment): the same planes the conformant mode uses for orthographic
//!   triangles, now for every triangle; no dithering. It earns its place on perspective
//!   scenes, where it saves the 1/w plane, a divide and a multiply per attribute per
//!   fragment; on orthographic scenes it is the conformant mode (same bytes, same time).
//! - [`Accuracy::Exact`]: z, colors and varyings from barycentric coordinates computed in
//!   f64 at each pixel centre, perspective-correct, rounded once to f32 for the fragment
//!   stages; the reference the benchmark measures the other modes against.

/// A named accuracy mode (the values of `TESSERA_ACCURACY_*` in `GL/tessera.h`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Accuracy {
    Fast = 1,
    #[default]
    Conformant = 0,
    Exact = 2,
}

impl Accuracy {
    /// Every mode, in the order the benchmark lists them.
    pub const ALL: [Accuracy; 3] = [Accuracy::Fast, Accuracy::Conformant, Accuracy::Exact];

    /// The mode of a `TESSERA_ACCURACY` value (`fast`, `conformant`, `exact`, any case).
    pub fn from_name(name: &str) -> Option<Accuracy> {
        match name.trim().to_ascii_lowercase().as_str() {
            "fast" => Some(Accuracy::Fast),
            "conformant" | "default" => Some(Accuracy::Conformant),
            "exact" => Some(Accuracy::Exact),
            _ => None,
        }
    }

    /// The mode of a `TESSERA_ACCURACY_*` code.
    pub fn from_code(code: i32) -> Option<Accuracy> {
        Accuracy::ALL.into_iter().find(|a| *a as i32 == code)
    }

    pub fn name(self) -> &'static str {
        match self {
            Accuracy::Fast => "fast",
            Accuracy::Conformant => "conformant",
            Accuracy::Exact => "exact",
        }
    }

    /// The mode `TESSERA_ACCURACY` names; the default when unset. An unknown name is
    /// reported once on stderr and gives the default.
    pub fn from_env() -> Accuracy {
        let Ok(value) = std::env::var("TESSERA_ACCURACY") else {
            return Accuracy::default();
        };
        Accuracy::from_name(&value).unwrap_or_else(|| {
            static WARNED: std::sync::Once = std::sync::Once::new();
            WARNED.call_once(|| {
                eprintln!("tessera: unknown TESSERA_ACCURACY={value:?} (fast, conformant, exact); using conformant")
            });
            Accuracy::default()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_codes_round_trip() {
        for a in Accuracy::ALL {
            assert_eq!(Accuracy::from_name(a.name()), Some(a));
            assert_eq!(Accuracy::from_name(&a.name().to_uppercase()), Some(a));
            assert_eq!(Accuracy::from_code(a as i32), Some(a));
        }
        assert_eq!(Accuracy::from_name("precise"), None);
        assert_eq!(Accuracy::from_code(3), None);
        assert_eq!(Accuracy::default(), Accuracy::Conformant);
    }
}
