//! GLX framebuffer configurations: what tessera offers on each X visual, their attributes,
//! and the selection rules of glXChooseFBConfig and glXChooseVisual.
//!
//! tessera renders into its own buffers and shows them with XPutImage, so any TrueColor (or
//! DirectColor) visual with 8-bit channels can carry every combination of buffers: single or
//! double buffered, depth 0/16/24, stencil 0/8, accumulation 0/16 and a software alpha
//! channel (8 bits kept in tessera's buffer, not in the window), plus double-buffered stereo
//! configurations, and multisampled configurations (GLX_SAMPLE_BUFFERS 1 with 2, 4 or 8
//! GLX_SAMPLES: double-buffered, depth 24, stencil 8, with and without alpha) whose
//! drawables render into multisample buffers and present the resolved image. This module is
//! pure data and rules, without X calls, so it is unit-tested.
use crate::framebuffer::{ColorFormat, DepthStencilFormat, FramebufferConfig};
use crate::gl::glx::*;
use crate::gl::limits::MAX_VIEWPORT_DIM;

/// X visual classes (X.h).
pub const X_TRUE_COLOR: i32 = 4;
pub const X_DIRECT_COLOR: i32 = 5;

/// An X visual tessera can render for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VisualDesc {
    pub screen: i32,
    pub visual_id: u64,
    pub class: i32,
    pub depth: i32,
    pub masks: [u64; 3],
}

impl VisualDesc {
    /// TrueColor or DirectColor with three 8-bit channels.
    pub fn usable(&self) -> bool {
        let eight_bits = |m: u64| m.count_ones() == 8 && (m >> m.trailing_zeros()) == 0xff;
        (self.class == X_TRUE_COLOR || self.class == X_DIRECT_COLOR) && self.masks.iter().all(|&m| eight_bits(m))
    }
}

/// One framebuffer configuration (GLXFBConfig).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FbConfig {
    /// GLX_FBCONFIG_ID: unique per display, from 1.
    pub id: i32,
    pub visual: VisualDesc,
    pub alpha: i32,
    pub double_buffered: bool,
    pub stereo: bool,
    pub depth: i32,
    pub stencil: i32,
    /// Bits per channel of the accumulation buffer.
    pub accum: i32,
    /// GLX_SAMPLES: 0 for a configuration without a multisample buffer.
    pub samples: i32,
}

impl FbConfig {
    /// Samples per pixel of a drawable's buffers (1 without a multisample buffer).
    pub fn sample_count(&self) -> usize {
        self.samples.max(1) as usize
    }

    /// The buffers a drawable of this configuration has.
    pub fn framebuffer_config(&self) -> FramebufferConfig {
        let depth_stencil = match (self.depth, self.stencil > 0) {
            (0, false) => DepthStencilFormat::None,
            (0, true) => DepthStencilFormat::Packed24 { depth: false, stencil: true },
            (16, false) => DepthStencilFormat::Depth16,
            (_, stencil) => DepthStencilFormat::Packed24 { depth: true, stencil },
        };
        FramebufferConfig {
            color: ColorFormat::Unorm8 { alpha: self.alpha > 0 },
            double_buffered: self.double_buffered,
            stereo: self.stereo,
            aux_buffers: 0,
            depth_stencil,
            accum_bits: self.accum as u32,
        }
    }

    /// glXGetFBConfigAttrib / glXGetConfig: the value of `attribute`, `None` if unknown.
    pub fn attrib(&self, attribute: i32) -> Option<i32> {
        let visual_type = if self.visual.class == X_DIRECT_COLOR { GLX_DIRECT_COLOR } else { GLX_TRUE_COLOR };
        Some(match attribute {
            GLX_USE_GL | GLX_RGBA | GLX_X_RENDERABLE => 1,
            GLX_FBCONFIG_ID => self.id,
            GLX_BUFFER_SIZE => 24 + self.alpha,
            GLX_LEVEL | GLX_AUX_BUFFERS => 0,
            GLX_SAMPLE_BUFFERS => i32::from(self.samples > 0),
            GLX_SAMPLES => self.samples,
            GLX_DOUBLEBUFFER => self.double_buffered as i32,
            GLX_STEREO => self.stereo as i32,
            GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE => 8,
            GLX_ALPHA_SIZE => self.alpha,
            GLX_DEPTH_SIZE => self.depth,
            GLX_STENCIL_SIZE => self.stencil,
            GLX_ACCUM_RED_SIZE..=GLX_ACCUM_ALPHA_SIZE => self.accum,
            GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE => GLX_NONE,
            GLX_TRANSPARENT_INDEX_VALUE..=GLX_TRANSPARENT_ALPHA_VALUE => 0,
            GLX_X_VISUAL_TYPE => visual_type,
            GLX_VISUAL_ID => self.visual.visual_id as i32,
            GLX_SCREEN => self.visual.screen,
            GLX_DRAWABLE_TYPE => GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT,
            GLX_RENDER_TYPE => GLX_RGBA_BIT,
            GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT => MAX_VIEWPORT_DIM,
            GLX_MAX_PBUFFER_PIXELS => MAX_VIEWPORT_DIM.saturating_mul(MAX_VIEWPORT_DIM),
            GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB => 0,
            // Swaps copy the back buffer to the front one.
            GLX_SWAP_METHOD_OML => GLX_SWAP_COPY_OML,
            _ => return None,
        })
    }

    /// The most capable configuration of a visual: what a context created for a visual that
    /// glXChooseVisual never returned gets.
    pub fn is_default_for_visual(&self) -> bool {
        self.double_buffered
            && !self.stereo
            && self.depth == 24
            && self.stencil == 8
            && self.accum == 16
            && self.alpha == 8
            && self.samples == 0
    }
}

impl VisualDesc {
    /// Whether pixels of `self` and `other` are the same (drawables of either visual can
    /// use the configurations of the other).
    pub fn equivalent(&self, other: &VisualDesc) -> bool {
        (self.screen, self.class, self.depth, self.masks) == (other.screen, other.class, other.depth, other.masks)
    }
}

/// Every configuration for the usable visuals of `visuals`, numbered from 1. Of equivalent
/// visuals only the first gets configurations (a server with GLX of its own, like Xvfb,
/// has hundreds of identical TrueColor visuals, one per server-side configuration).
pub fn configs_for(visuals: &[VisualDesc]) -> Vec<FbConfig> {
    let mut configs = Vec::new();
    let mut seen: Vec<VisualDesc> = Vec::new();
    for visual in visuals.iter().filter(|v| v.usable()) {
        if seen.iter().any(|s| s.equivalent(visual)) {
            continue;
        }
        seen.push(*visual);
        let mut push = |double_buffered, stereo, depth, stencil, accum, alpha, samples| {
            let id = configs.len() as i32 + 1;
            let visual = *visual;
            configs.push(FbConfig { id, visual, alpha, double_buffered, stereo, depth, stencil, accum, samples });
        };
        for double_buffered in [false, true] {
            for (depth, stencil) in [(0, 0), (16, 0), (24, 0), (24, 8), (0, 8)] {
                for accum in [0, 16] {
                    for alpha in [0, 8] {
                        push(double_buffered, false, depth, stencil, accum, alpha, 0);
                    }
                }
            }
        }
        for double_buffered in [false, true] {
            push(double_buffered, true, 24, 8, 0, 8, 0);
        }
        for samples in [2, 4, 8] {
            for alpha in [0, 8] {
                push(true, false, 24, 8, 0, alpha, samples);
            }
        }
    }
    configs
}

/// A parsed attribute list of glXChooseFBConfig or glXChooseVisual.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Criteria {
    double_buffered: Option<bool>,
    stereo: Option<bool>,
    buffer_size: i32,
    level: i32,
    aux_buffers: i32,
    color: [i32; 4],
    depth: i32,
    stencil: i32,
    accum: [i32; 4],
    render_type: i32,
    drawable_type: i32,
    x_renderable: Option<bool>,
    visual_type: Option<i32>,
    caveat: Option<i32>,
    transparent: Option<i32>,
    fbconfig_id: Option<i32>,
    /// GLX_SAMPLE_BUFFERS and GLX_SAMPLES: minimums (GLX 1.4 table 3.4).
    sample_buffers: i32,
    samples: i32,
    /// glXChooseVisual's preference rules instead of glXChooseFBConfig's sort.
    visual_rules: bool,
}

/// Why an attribute list was refused.
#[derive(Debug, PartialEq, Eq)]
pub enum BadAttribute {
    /// Not an attribute of this call (GLX_BAD_ATTRIBUTE).
    Unknown(i32),
    /// Color-index rendering (tessera renders RGBA only).
    ColorIndex,
}

fn dont_care_or(value: i32) -> Option<i32> {
    (value != GLX_DONT_CARE).then_some(value)
}

fn at_least(value: i32) -> i32 {
    if value == GLX_DONT_CARE {
        0
    } else {
        value
    }
}

impl Criteria {
    fn defaults(visual_rules: bool) -> Criteria {
        Criteria {
            double_buffered: if visual_rules { Some(false) } else { None },
            stereo: Some(false),
            buffer_size: 0,
            level: 0,
            aux_buffers: 0,
            color: [0; 4],
            depth: 0,
            stencil: 0,
            accum: [0; 4],
            render_type: GLX_RGBA_BIT,
            drawable_type: GLX_WINDOW_BIT,
            x_renderable: None,
            visual_type: None,
            caveat: None,
            transparent: Some(GLX_NONE),
            fbconfig_id: None,
            sample_buffers: 0,
            samples: 0,
            visual_rules,
        }
    }

    /// glXChooseFBConfig's list: attribute/value pairs up to `None` (0).
    pub fn fbconfig(list: &[i32]) -> Result<Criteria, BadAttribute> {
        let mut c = Criteria::defaults(false);
        for pair in list.chunks(2) {
            let (attribute, value) = (pair[0], pair.get(1).copied().unwrap_or(0));
            match attribute {
                GLX_DOUBLEBUFFER => c.double_buffered = dont_care_or(value).map(|v| v != 0),
                GLX_STEREO => c.stereo = dont_care_or(value).map(|v| v != 0),
                GLX_X_RENDERABLE => c.x_renderable = dont_care_or(value).map(|v| v != 0),
                GLX_RENDER_TYPE => c.render_type = if value == GLX_DONT_CARE { GLX_RGBA_BIT } else { value },
                GLX_DRAWABLE_TYPE => c.drawable_type = if value == GLX_DONT_CARE { 0 } else { value },
                GLX_X_VISUAL_TYPE => c.visual_type = dont_care_or(value),
                GLX_CONFIG_CAVEAT => c.caveat = dont_care_or(value),
                GLX_TRANSPARENT_TYPE => c.transparent = dont_care_or(value),
                GLX_FBCONFIG_ID => c.fbconfig_id = dont_care_or(value),
                GLX_TRANSPARENT_INDEX_VALUE..=GLX_TRANSPARENT_ALPHA_VALUE => {}
                GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT | GLX_MAX_PBUFFER_PIXELS => {}
                // Swap method and sRGB capability: every configuration copies on swap and
                // none is sRGB, so asking for either only narrows an empty difference.
                GLX_SWAP_METHOD_OML | GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB => {}
                GLX_VISUAL_ID => {}
                other => c.sized(other, value)?,
            }
        }
        Ok(c)
    }

    /// glXChooseVisual's list: boolean attributes alone, the others followed by a value.
    pub fn visual(list: &[i32]) -> Result<Criteria, BadAttribute> {
        let mut c = Criteria::defaults(true);
        let mut rgba = false;
        let mut i = 0;
        while i < list.len() {
            let attribute = list[i];
            match attribute {
                GLX_USE_GL => {}
                GLX_RGBA => rgba = true,
                GLX_DOUBLEBUFFER => c.double_buffered = Some(true),
                GLX_STEREO => c.stereo = Some(true),
                _ => {
                    let value = list.get(i + 1).copied().unwrap_or(0);
                    i += 1;
                    c.sized(attribute, value)?;
                }
            }
            i += 1;
        }
        if !rgba {
            return Err(BadAttribute::ColorIndex);
        }
        Ok(c)
    }

    fn sized(&mut self, attribute: i32, value: i32) -> Result<(), BadAttribute> {
        let v = at_least(value);
        match attribute {
            GLX_BUFFER_SIZE => self.buffer_size = v,
            GLX_LEVEL => self.level = value,
            GLX_AUX_BUFFERS => self.aux_buffers = v,
            GLX_RED_SIZE..=GLX_ALPHA_SIZE => self.color[(attribute - GLX_RED_SIZE) as usize] = v,
            GLX_DEPTH_SIZE => self.depth = v,
            GLX_STENCIL_SIZE => self.stencil = v,
            GLX_ACCUM_RED_SIZE..=GLX_ACCUM_ALPHA_SIZE => self.accum[(attribute - GLX_ACCUM_RED_SIZE) as usize] = v,
            GLX_SAMPLE_BUFFERS => self.sample_buffers = v,
            GLX_SAMPLES => self.samples = v,
            other => return Err(BadAttribute::Unknown(other)),
        }
        Ok(())
    }

    /// Whether `config` satisfies every criterion.
    pub fn matches(&self, config: &FbConfig) -> bool {
        if let Some(id) = self.fbconfig_id {
            // GLX 1.4: with GLX_FBCONFIG_ID, every other attribute is ignored.
            return config.id == id;
        }
        let a = |attribute| config.attrib(attribute).unwrap_or(0);
        let sizes_ok = self.color.iter().enumerate().all(|(i, &c)| a(GLX_RED_SIZE + i as i32) >= c)
            && self.accum.iter().enumerate().all(|(i, &c)| a(GLX_ACCUM_RED_SIZE + i as i32) >= c);
        sizes_ok
            && self.double_buffered.is_none_or(|d| d == config.double_buffered)
            && self.stereo.is_none_or(|s| s == config.stereo)
            && a(GLX_BUFFER_SIZE) >= self.buffer_size
            && self.level == 0
            && self.aux_buffers == 0
            && config.depth >= self.depth
            && config.stencil >= self.stencil
            && a(GLX_SAMPLE_BUFFERS) >= self.sample_buffers
            && config.samples >= self.samples
            && self.render_type & GLX_RGBA_BIT != 0
            && self.drawable_type & !(GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT) == 0
            && self.x_renderable.is_none_or(|r| r)
            && self.visual_type.is_none_or(|t| t == a(GLX_X_VISUAL_TYPE))
            && self.caveat.is_none_or(|c| c == GLX_NONE)
            && self.transparent.is_none_or(|t| t == GLX_NONE)
    }

    /// The sort key of GLX 1.4 section 3.3.3 (glXChooseFBConfig) or of glXChooseVisual's
    /// preferences: smaller keys come first.
    fn sort_key(&self, config: &FbConfig) -> [i64; 10] {
        let prefer = |requested: i32, have: i32| -> i64 {
            // Larger when asked for, otherwise none (the smallest).
            if requested > 0 {
                -(have as i64)
            } else {
                have as i64
            }
        };
        let requested_color: i64 = (0..4)
            .filter(|&i| self.color[i] > 0)
            .map(|i| config.attrib(GLX_RED_SIZE + i as i32).unwrap_or(0) as i64)
            .sum();
        let accum_sum = config.accum * 4;
        let accum_requested = self.accum.iter().any(|&a| a > 0) as i32;
        let depth = if self.visual_rules { prefer(self.depth, config.depth) } else { -(config.depth as i64) };
        let visual_type = if config.visual.class == X_TRUE_COLOR { 0 } else { 1 };
        [
            -requested_color,
            config.attrib(GLX_BUFFER_SIZE).unwrap_or(0) as i64,
            config.double_buffered as i64,
            // GLX_SAMPLE_BUFFERS and GLX_SAMPLES: smaller first.
            i64::from(config.samples > 0),
            config.samples as i64,
            depth,
            config.stencil as i64,
            prefer(accum_requested, accum_sum),
            visual_type,
            config.visual.depth as i64,
        ]
    }

    /// The configurations of `configs` on `screen` that match, best first.
    pub fn choose<'a>(&self, configs: &'a [FbConfig], screen: i32) -> Vec<&'a FbConfig> {
        let mut chosen: Vec<&FbConfig> =
            configs.iter().filter(|c| c.visual.screen == screen && self.matches(c)).collect();
        chosen.sort_by_key(|c| (self.sort_key(c), c.id));
        chosen
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn visuals() -> Vec<VisualDesc> {
        let rgb = [0xff0000, 0xff00, 0xff];
        vec![
            VisualDesc { screen: 0, visual_id: 0x21, class: X_TRUE_COLOR, depth: 24, masks: rgb },
            VisualDesc { screen: 0, visual_id: 0x22, class: X_DIRECT_COLOR, depth: 24, masks: rgb },
            VisualDesc { screen: 0, visual_id: 0x23, class: 3, depth: 8, masks: [0; 3] },
            VisualDesc { screen: 0, visual_id: 0x24, class: X_TRUE_COLOR, depth: 16, masks: [0xf800, 0x7e0, 0x1f] },
            VisualDesc { screen: 0, visual_id: 0x25, class: X_TRUE_COLOR, depth: 24, masks: rgb },
        ]
    }

    #[test]
    fn configs_cover_every_combination_on_usable_visuals_only() {
        let configs = configs_for(&visuals());
        // 40 single-sampled mono, 2 stereo and 6 multisampled configurations per visual.
        assert_eq!(configs.len(), 2 * 48);
        assert!(configs.iter().all(|c| c.visual.visual_id == 0x21 || c.visual.visual_id == 0x22));
        let ids: Vec<i32> = configs.iter().map(|c| c.id).collect();
        assert_eq!(ids, (1..=96).collect::<Vec<_>>());
        for (d, s) in [(0, 0), (16, 0), (24, 0), (24, 8), (0, 8)] {
            for double in [false, true] {
                for accum in [0, 16] {
                    assert!(configs.iter().any(|c| c.depth == d
                        && c.stencil == s
                        && c.double_buffered == double
                        && c.accum == accum
                        && !c.stereo));
                }
            }
        }
        let stereo = configs.iter().find(|c| c.stereo).unwrap();
        assert!(stereo.framebuffer_config().stereo);
    }

    #[test]
    fn framebuffer_config_has_the_advertised_buffers() {
        let configs = configs_for(&visuals());
        for c in &configs {
            let fb = c.framebuffer_config();
            assert_eq!(fb.depth_stencil.depth_bits() as i32, c.depth, "{c:?}");
            assert_eq!(fb.depth_stencil.stencil_bits() as i32, c.stencil, "{c:?}");
            assert_eq!(fb.accum_bits as i32, c.accum);
            assert_eq!(fb.double_buffered, c.double_buffered);
            assert_eq!(fb.color.has_alpha(), c.alpha > 0);
        }
    }

    #[test]
    fn choose_fbconfig_matches_and_sorts_as_glx_says() {
        let configs = configs_for(&visuals());
        let c = Criteria::fbconfig(&[GLX_DOUBLEBUFFER, 1, GLX_DEPTH_SIZE, 16, GLX_RED_SIZE, 1]).unwrap();
        let chosen = c.choose(&configs, 0);
        assert!(!chosen.is_empty());
        assert!(chosen.iter().all(|c| c.double_buffered && c.depth >= 16 && !c.stereo));
        // Larger depth first, then the smallest stencil, no alpha and no accumulation buffer.
        let best = chosen[0];
        assert_eq!((best.depth, best.stencil, best.alpha, best.accum), (24, 0, 0, 0));
        assert_eq!(best.visual.class, X_TRUE_COLOR);
        // Alpha asked for: alpha configurations only.
        let c = Criteria::fbconfig(&[GLX_ALPHA_SIZE, 1, GLX_STENCIL_SIZE, 1]).unwrap();
        let chosen = c.choose(&configs, 0);
        assert!(chosen.iter().all(|c| c.alpha == 8 && c.stencil == 8));
        assert!(!chosen[0].double_buffered);
        // Nothing on another screen, nothing with samples, and GLX_FBCONFIG_ID picks one.
        assert!(c.choose(&configs, 1).is_empty());
        assert_eq!(c.choose(&configs, 0)[0].samples, 0, "multisampled ones sort after");
        let by_id = Criteria::fbconfig(&[GLX_FBCONFIG_ID, 7, GLX_STEREO, 1]).unwrap().choose(&configs, 0);
        assert_eq!(by_id.iter().map(|c| c.id).collect::<Vec<_>>(), vec![7]);
        assert_eq!(Criteria::fbconfig(&[0x7777, 1]), Err(BadAttribute::Unknown(0x7777)));
        // GLX_DONT_CARE on the double buffer gives both kinds.
        let any = Criteria::fbconfig(&[GLX_DOUBLEBUFFER, GLX_DONT_CARE]).unwrap().choose(&configs, 0);
        assert!(any.iter().any(|c| c.double_buffered) && any.iter().any(|c| !c.double_buffered));
    }

    #[test]
    fn multisample_configurations_are_chosen_by_their_minimum_samples() {
        let configs = configs_for(&visuals());
        let c = Criteria::fbconfig(&[GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 4, GLX_DOUBLEBUFFER, 1]).unwrap();
        let chosen = c.choose(&configs, 0);
        assert!(chosen.iter().all(|c| c.samples >= 4));
        // The smallest sample count that satisfies the request comes first.
        assert_eq!(chosen[0].samples, 4);
        assert_eq!((chosen[0].attrib(GLX_SAMPLE_BUFFERS), chosen[0].attrib(GLX_SAMPLES)), (Some(1), Some(4)));
        assert_eq!(chosen[0].sample_count(), 4);
        let c = Criteria::fbconfig(&[GLX_SAMPLE_BUFFERS, 1]).unwrap();
        assert_eq!(c.choose(&configs, 0)[0].samples, 2);
        assert!(Criteria::fbconfig(&[GLX_SAMPLES, 16]).unwrap().choose(&configs, 0).is_empty());
        let c = Criteria::visual(&[GLX_RGBA, GLX_DOUBLEBUFFER, GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 8]).unwrap();
        assert_eq!(c.choose(&configs, 0)[0].samples, 8);
        // Without a request, no multisampled configuration comes before a single-sampled one.
        let any = Criteria::fbconfig(&[GLX_DOUBLEBUFFER, 1, GLX_DEPTH_SIZE, 24]).unwrap().choose(&configs, 0);
        assert_eq!(any[0].samples, 0);
    }

    #[test]
    fn choose_visual_uses_its_own_defaults_and_preferences() {
        let configs = configs_for(&visuals());
        assert_eq!(Criteria::visual(&[GLX_DOUBLEBUFFER]), Err(BadAttribute::ColorIndex));
        let c = Criteria::visual(&[GLX_RGBA, GLX_RED_SIZE, 1, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1]).unwrap();
        let best = c.choose(&configs, 0)[0];
        assert!(best.double_buffered);
        assert_eq!((best.depth, best.stencil, best.accum, best.alpha), (24, 0, 0, 0));
        // Without GLX_DOUBLEBUFFER only single-buffered visuals; depth 0 prefers none.
        let c = Criteria::visual(&[GLX_RGBA, GLX_ACCUM_RED_SIZE, 1]).unwrap();
        let chosen = c.choose(&configs, 0);
        assert!(chosen.iter().all(|c| !c.double_buffered && c.accum == 16));
        assert_eq!(chosen[0].depth, 0);
    }
}
