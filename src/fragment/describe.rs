//! How a compiled fragment pipeline reads to a person: the stages a draw runs, in order.
//!
//! `TESSERA_DEBUG=pipeline` prints this for every draw (see `context::draw`), so a user can
//! see that a disabled test is absent from the pipeline rather than skipped per pixel, and
//! where the depth and stencil tests run: *early* (before the fragment colors are computed,
//! which are then computed only for the survivors) whenever no stage before them can
//! discard a fragment, i.e. without the alpha test or a GLSL shader that may discard or
//! writes the depth; *late* (after the colors) otherwise.

use super::blend::{Blend, BlendFunc};
use super::stencil::StencilFace;
use super::FragmentState;
use std::fmt::{self, Display, Formatter, Write};

/// Whether the depth/stencil tests of `state` run before the colors are computed.
pub fn early_depth_stencil(state: &FragmentState) -> bool {
    state.alpha.is_none() && !state.late_tests()
}

impl Display for FragmentState {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let mut stages: Vec<String> = Vec::new();
        let tests = self.depth.is_some() || self.stencil.is_some();
        let early = tests && early_depth_stencil(self);
        if early {
            stages.push(self.tests_stage("early "));
        }
        stages.push(if self.glsl.is_some() { "shade (GLSL)" } else { "shade" }.to_string());
        if let Some(alpha) = &self.alpha {
            let precision = if alpha.unorm8 { "8-bit" } else { "float" };
            stages.push(format!("alpha {:?} {} ({precision})", alpha.func, alpha.reference));
        }
        if tests && !early {
            stages.push(self.tests_stage("late "));
        }
        if self.color_sum {
            stages.push("color sum".to_string());
        }
        if let Some(fog) = &self.fog {
            stages.push(format!("fog {:?}", fog.mode));
        }
        let mut targets = String::new();
        for (index, mask) in self.color_masks.iter().enumerate() {
            let Some(mask) = mask else { continue };
            if !targets.is_empty() {
                targets.push_str(", ");
            }
            let _ = write!(targets, "target {index}:");
            if let Some(Some(blend)) = self.blend.get(index) {
                let _ = write!(targets, " blend {}", BlendText(blend));
            }
            if let Some(op) = self.logic_op {
                let _ = write!(targets, " logic op {op:?}");
            }
            if self.dither {
                targets.push_str(" dither");
            }
            let channels: String = mask.iter().zip("RGBA".chars()).map(|(&on, c)| if on { c } else { '-' }).collect();
            let _ = write!(targets, " write {channels}");
        }
        if targets.is_empty() {
            targets.push_str("no color target");
        }
        stages.push(targets);
        write!(f, "{}", stages.join(" → "))
    }
}

impl FragmentState {
    fn tests_stage(&self, when: &str) -> String {
        let mut text = String::from(when);
        if let Some(stencil) = &self.stencil {
            if stencil.front == stencil.back {
                let _ = write!(text, "stencil({}) ", FaceText(&stencil.front));
            } else {
                let _ = write!(text, "stencil front({}) back({}) ", FaceText(&stencil.front), FaceText(&stencil.back));
            }
        }
        match &self.depth {
            Some(depth) => {
                let _ = write!(text, "depth {:?}{}", depth.func, if depth.write { " write" } else { "" });
                if let Some([min, max]) = self.depth_clamp {
                    let _ = write!(text, " clamped to [{min}, {max}]");
                }
            }
            None => text.push_str("(no depth test)"),
        }
        text
    }
}

struct FaceText<'a>(&'a StencilFace);

impl Display for FaceText<'_> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let s = self.0;
        write!(
            f,
            "{:?} ref {} mask {:#04x} write {:#04x}; {:?}/{:?}/{:?}",
            s.func, s.reference, s.value_mask, s.write_mask, s.sfail, s.zfail, s.zpass
        )
    }
}

struct BlendText<'a>(&'a Blend);

impl Display for BlendText<'_> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let func = |b: &BlendFunc| format!("{:?}({:?}, {:?})", b.equation, b.src, b.dst);
        if self.0.rgb == self.0.alpha {
            write!(f, "{}", func(&self.0.rgb))
        } else {
            write!(f, "rgb {} alpha {}", func(&self.0.rgb), func(&self.0.alpha))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::blend::{BlendEquation, BlendFactor};
    use super::super::{AlphaTest, DepthTest};
    use super::*;
    use crate::gl::CompareFunc;

    #[test]
    fn disabled_stages_are_not_described_and_early_tests_come_first() {
        let depth = Some(DepthTest { func: CompareFunc::Less, write: true });
        let mut state = FragmentState::plain(depth, vec![Some([true, true, true, false]), None], false);
        assert_eq!(state.to_string(), "early depth Less write → shade → target 0: write RGB-");
        let func =
            BlendFunc { src: BlendFactor::SrcAlpha, dst: BlendFactor::OneMinusSrcAlpha, equation: BlendEquation::Add };
        state.blend[0] = Some(Blend { rgb: func, alpha: func });
        state.alpha = Some(AlphaTest { func: CompareFunc::Greater, reference: 0.5, unorm8: true });
        assert_eq!(
            state.to_string(),
            "shade → alpha Greater 0.5 (8-bit) → late depth Less write → \
             target 0: blend Add(SrcAlpha, OneMinusSrcAlpha) write RGB-"
        );
        assert!(!early_depth_stencil(&state));
        let none = FragmentState::plain(None, vec![None], false);
        assert_eq!(none.to_string(), "shade → no color target");
    }
}
