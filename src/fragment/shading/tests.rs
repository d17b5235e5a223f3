//! The block and span runs of a fragment program against each other (the same bits on every
//! lane, whatever the quads' rows and the mask), and a span without derivatives against a
//! per-fragment evaluation.

use super::*;
use crate::fragment::fog::{Fog, FogMode};
use crate::texture::env;
use crate::texture::sampler::{DepthMode, Dim, Filter, Sampler, Wrap};
use crate::texture::{depth_storage, BaseFormat, TexImage, Texels, TextureStage};
use std::cell::Cell;

/// A small deterministic generator (xorshift).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// The shading of `state` (texturing, colour sum, fog), its program generated here.
fn shading_of(state: &FragmentState) -> Shading {
    let key = FragmentKey::of(state);
    Shading::new(Arc::new(CompiledFragment::generate(&key)), state)
}

#[test]
fn quads_of_a_mask() {
    assert_eq!(quads(0), 0);
    assert_eq!(quads(1), 0b0011_0011);
    assert_eq!(quads(1 << 15), 0xcc00);
    assert_eq!(quads(1 << 10), 0xcc00);
    assert_eq!(quads(1 << 6), 0x00cc);
    assert_eq!(quads(0x8421), 0xcc33, "lanes 0 and 5 share a quad, as 10 and 15 do");
    assert_eq!(quads(0x0180), 0x33cc);
}

/// Random draws of one to three units (every kernel: RGBA8 2D, depth with comparison,
/// a bordered or clamped 2D image and a cube map through the reference; every classic
/// environment and GL_COMBINE), with and without the colour sum and fog, on framebuffers
/// of odd and even heights: each block shaded over its lanes gives the bits of the span
/// runs on its rows, whatever the mask. A wrong lane order, a quad of the wrong rows or
/// derivatives taken the wrong way round change levels of detail (the coordinates vary
/// anisotropically, with perspective) and so colours.
// A lane indexes coordinates, colours and masks alike.
#[allow(clippy::needless_range_loop)]
#[test]
fn blocks_shade_as_spans_do() {
    let mut rng = Rng(0x5851_f42d_4c95_7f2d);
    let rgba_chain = |rng: &mut Rng, w: usize, h: usize, border: usize| -> Vec<Arc<TexImage>> {
        let (mut w, mut h) = (w, h);
        let mut levels = Vec::new();
        loop {
            let (bw, bh) = (w + 2 * border, h + 2 * border);
            let mut img = TexImage::new(bw, bh, 1, border, BaseFormat::Rgba).unwrap();
            img.texels = Texels::Rgba8((0..bw * bh).map(|_| (rng.next() as u32).to_le_bytes()).collect());
            levels.push(Arc::new(img));
            if w == 1 && h == 1 {
                return levels;
            }
            (w, h) = ((w / 2).max(1), (h / 2).max(1));
        }
    };
    let mut depth = TexImage::new_depth(16, 16, 1, 0, depth_storage(24, true, false)).unwrap();
    for i in 0..256 {
        depth.set_depth_f32(i, rng.unit());
    }
    let depth = Arc::new(depth);
    let wraps = [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat, Wrap::ClampToBorder, Wrap::Clamp];
    let filters = [Filter::Nearest, Filter::Linear];
    let mips = [None, Some(Filter::Nearest), Some(Filter::Linear)];
    let modes = [
        env::EnvMode::Modulate,
        env::EnvMode::Replace,
        env::EnvMode::Decal,
        env::EnvMode::Blend,
        env::EnvMode::Add,
        env::EnvMode::Combine(env::Combine {
            rgb: env::CombineFn::Interpolate,
            alpha: env::CombineFn::Modulate,
            src_rgb: [env::Source::Texture, env::Source::Previous, env::Source::PrimaryColor],
            op_rgb: [env::Operand { alpha: false, invert: false }; 3],
            src_alpha: [env::Source::Texture, env::Source::TextureUnit(0), env::Source::Constant],
            op_alpha: [env::Operand { alpha: true, invert: true }; 3],
            scale_rgb: 2.0,
            scale_alpha: 1.0,
        }),
    ];
    let bases =
        [BaseFormat::Rgba, BaseFormat::Rgb, BaseFormat::Intensity, BaseFormat::Alpha, BaseFormat::LuminanceAlpha];
    let mut compared = 0;
    let mut differ = 0;
    for draw in 0..60 {
        let mut state = FragmentState::plain(None, Vec::new(), true);
        state.color_sum = rng.below(2) == 0;
        state.fog = [None, Some(FogMode::Linear), Some(FogMode::Exp)][rng.below(3)].map(|mode| Fog {
            mode,
            start: 0.0,
            end: 2.0,
            density: 0.7,
            color: [0.25, 0.5, 0.75, 1.0],
        });
        let first = 3 * usize::from(state.color_sum) + usize::from(state.fog.is_some());
        let units = 1 + rng.below(3);
        let mut stages = Vec::new();
        for unit in 0..units {
            let kind = rng.below(5);
            let mip = mips[rng.below(3)];
            let (dim, faces, compare, wrap) = match kind {
                // RGBA8 2D: the specialised kernel.
                0 | 1 => (
                    Dim::D2,
                    {
                        let (w, h) = (8 << rng.below(3), 4 << rng.below(3));
                        vec![rgba_chain(&mut rng, w, h, 0)]
                    },
                    None,
                    [wraps[rng.below(3)], wraps[rng.below(3)], Wrap::Repeat],
                ),
                // Depth with comparison (the shadow-map kernel).
                2 => (
                    Dim::D2,
                    vec![vec![depth.clone()]],
                    Some(crate::gl::CompareFunc::LessEqual),
                    [wraps[rng.below(3)], Wrap::ClampToEdge, Wrap::Repeat],
                ),
                // A bordered image, clamped to its border: the reference.
                3 => (
                    Dim::D2,
                    vec![rgba_chain(&mut rng, 8, 8, 1)],
                    None,
                    [wraps[3 + rng.below(2)], Wrap::ClampToBorder, Wrap::Repeat],
                ),
                // A cube map: the reference.
                _ => (Dim::Cube, (0..6).map(|_| rgba_chain(&mut rng, 4, 4, 0)).collect(), None, [Wrap::ClampToEdge; 3]),
            };
            let mip = if kind == 2 { None } else { mip };
            let sampler = Sampler {
                dim,
                faces,
                wrap,
                mag: filters[rng.below(2)],
                min: filters[rng.below(2)],
                mip,
                border: [0.25, 0.5, 0.75, 1.0],
                lod_bias: [0.0, 0.5, -1.0][rng.below(3)],
                shader_bias: 0.0,
                min_lod: -1000.0,
                max_lod: 1000.0,
                compare,
                depth_mode: DepthMode::Intensity,
                base: BaseFormat::Rgba,
            };
            let mode = modes[rng.below(modes.len())];
            let base = bases[rng.below(bases.len())];
            let env = env::TexEnv { mode, base, color: [0.2, 0.4, 0.6, 0.8] };
            stages.push(TextureStage::new(unit, sampler, env, first + 4 * unit));
        }
        let fb_height = [7, 8, 9, 10, 13][draw % 5];
        state.texturing = Some(Arc::new(Texturing { stages, fb_height }));
        let shading = shading_of(&state);
        let texturing = state.texturing.as_deref();
        // Varyings: the colour sum's and fog's, then s, t, r, q per unit, planes with
        // perspective.
        let n = first + 4 * units;
        let planes: Vec<[f32; 3]> = (0..n)
            .map(|_| {
                let scale = [0.02, 0.2, 1.0][rng.below(3)];
                [rng.unit() * 2.0 - 0.5, (rng.unit() - 0.5) * scale, (rng.unit() - 0.5) * scale]
            })
            .collect();
        // w changing fast from row to row: the derivatives of a quad's two rows differ.
        let (qx, qy) = ((rng.unit() - 0.5) * 0.1, 0.05 + 0.4 * rng.unit());
        let at = |x: i32, y: i32, out: &mut [f32]| {
            let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
            let w = 1.0 + qx * x + qy * y;
            // s/q = plane/w: not affine in the window.
            for (o, p) in out.iter_mut().zip(&planes) {
                *o = p[0] + p[1] * x + p[2] * y;
            }
            for u in 0..units {
                if let Some(q) = out.get_mut(first + 4 * u + 3) {
                    *q = w;
                }
            }
        };
        let mut scratch = ShadingScratch::default();
        for (bx, by) in [(0, 0), (4, 4), (8, 0), (4, 8)] {
            let live = [0xffff, rng.next() as u16, 1 << rng.below(16), 0x8421][rng.below(4)];
            let primary = |x: i32, y: i32| [x as f32 / 12.0, y as f32 / 12.0, 0.5, 0.75];
            let mut colors = [[0.0; LANES]; 4];
            for i in 0..LANES {
                let p = primary(bx + (i & 3) as i32, by + (i >> 2) as i32);
                for k in 0..4 {
                    colors[k][i] = p[k];
                }
            }
            let before = colors;
            shading.run_block(
                crate::simd::current(),
                &mut scratch,
                texturing,
                by,
                live,
                &mut colors,
                |y0, first, out| {
                    for i in 0..LANES {
                        let mut v = vec![0.0; n];
                        at(bx + (i & 3) as i32, y0 + (i >> 2) as i32, &mut v);
                        for (k, o) in out.iter_mut().enumerate() {
                            o[i] = v.get(first + k).copied().unwrap_or(0.0);
                        }
                    }
                },
            );
            for r in 0..4 {
                let y = by + r as i32;
                // The row as a span from one column left of the block: another grouping of
                // its columns.
                let mut row: Vec<[f32; 4]> = (-1..4).map(|c| primary(bx + c, y)).collect();
                let row_live = (((live >> (4 * r)) & 0xf) as u64) << 1;
                shading.run_span(&mut scratch, texturing, bx - 1, y, row_live, &mut row, |dx, dy, out| {
                    at(bx - 1 + dx, y + dy, out)
                });
                for c in 0..4 {
                    let i = 4 * r + c;
                    let pixel = row[c + 1];
                    let lane: [f32; 4] = std::array::from_fn(|k| colors[k][i]);
                    if live & (1 << i) != 0 {
                        assert_eq!(
                            lane.map(f32::to_bits),
                            pixel.map(f32::to_bits),
                            "draw {draw} block ({bx}, {by}) lane {i} height {fb_height}"
                        );
                        compared += 1;
                        differ += usize::from(lane != std::array::from_fn(|k| before[k][i]));
                    } else {
                        // A block's lanes outside the mask hold unspecified colours (the
                        // pipeline reads only the live lanes'); a span's fragments outside
                        // its mask are left alone.
                        assert_eq!(pixel, primary(bx + c as i32, y), "a fragment outside the span's mask");
                    }
                }
            }
        }
    }
    assert!(compared > 1000 && differ > compared / 2, "{compared} {differ}");
}

#[test]
fn lookups_without_derivatives_evaluate_only_the_live_fragments() {
    // A depth texture with comparison and no mipmaps (a shadow map) on unit 1 and an
    // unmipmapped RGBA texture on unit 0: no λ, so no neighbour is evaluated, and each
    // fragment is what the sampler and the environments (the tests' reference) give for
    // its own coordinates.
    let mut depth = TexImage::new_depth(8, 8, 1, 0, depth_storage(24, true, false)).unwrap();
    for i in 0..64 {
        depth.set_depth_f32(i, (i % 7) as f32 / 6.0);
    }
    let mut rgba = TexImage::new(4, 4, 1, 0, BaseFormat::Rgba).unwrap();
    rgba.texels = Texels::Rgba8((0..16u8).map(|i| [i * 16, 255 - i * 9, i * 3, 200]).collect());
    let sampler = |image: TexImage, filter: Filter, compare| Sampler {
        dim: Dim::D2,
        faces: vec![vec![Arc::new(image)]],
        wrap: [Wrap::ClampToEdge, Wrap::Repeat, Wrap::Repeat],
        mag: filter,
        min: filter,
        mip: None,
        border: [0.0; 4],
        lod_bias: 0.0,
        shader_bias: 0.0,
        min_lod: -1000.0,
        max_lod: 1000.0,
        compare,
        depth_mode: DepthMode::Intensity,
        base: BaseFormat::Rgba,
    };
    let modulate = env::TexEnv { mode: env::EnvMode::Modulate, base: BaseFormat::Rgba, color: [0.0; 4] };
    let stages = vec![
        TextureStage::new(0, sampler(rgba, Filter::Linear, None), modulate, 0),
        TextureStage::new(1, sampler(depth, Filter::Nearest, Some(crate::gl::CompareFunc::GreaterEqual)), modulate, 4),
    ];
    assert!(stages.iter().all(|s| !s.needs_derivatives()));
    let h = 6;
    let mut state = FragmentState::plain(None, Vec::new(), true);
    state.texturing = Some(Arc::new(Texturing { stages, fb_height: h }));
    let shading = shading_of(&state);
    let texturing = state.texturing.as_deref().unwrap();
    let at = |x: i32, y: i32, out: &mut [f32]| {
        let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
        let q = 1.0 + 0.05 * x;
        out[..8].copy_from_slice(&[0.11 * x / q, 0.07 * y / q, 0.0, 1.0 / q, 0.1 * x, 0.13 * y, 0.08 * x, 1.0]);
    };
    let neighbours = Cell::new(0);
    let mut scratch = ShadingScratch::default();
    let primary = [0.5, 0.75, 1.0, 1.0];
    for y in 0..h {
        let live = 0b1101_1011u64;
        let mut colors = vec![primary; 8];
        shading.run_span(&mut scratch, Some(texturing), 3, y, live, &mut colors, |dx, dy, out| {
            neighbours.set(neighbours.get() + usize::from(dy != 0 || live & (1 << dx) == 0));
            at(3 + dx, y + dy, out)
        });
        for (i, color) in colors.iter().enumerate() {
            if live & (1 << i) == 0 {
                assert_eq!(*color, primary, "a fragment outside the span's mask");
                continue;
            }
            let mut v = [0.0; 8];
            at(3 + i as i32, y, &mut v);
            let mut expect = primary;
            let mut texels = [[0.0, 0.0, 0.0, 1.0]; crate::texture::MAX_UNITS];
            for s in &texturing.stages {
                let q = v[s.slot + 3];
                let inv = if q != 0.0 { 1.0 / q } else { 0.0 };
                let c = [v[s.slot] * inv, v[s.slot + 1] * inv, v[s.slot + 2] * inv];
                texels[s.unit] = s.sampler.sample(c, [0.0; 3], [0.0; 3]);
            }
            for s in &texturing.stages {
                expect = s.env.apply(s.unit, expect, primary, &texels);
            }
            assert_eq!(*color, expect, "pixel ({}, {y})", 3 + i);
        }
    }
    assert_eq!(neighbours.get(), 0, "no coordinates but the live fragments' are evaluated");
}

#[test]
fn a_program_that_passes_the_colour_through_is_none() {
    let state = FragmentState::plain(None, Vec::new(), true);
    assert!(is_identity(&FragmentKey::of(&state)));
    let mut fogged = state.clone();
    fogged.fog = Some(Fog { mode: FogMode::Linear, start: 0.0, end: 1.0, density: 1.0, color: [0.0; 4] });
    assert!(!is_identity(&FragmentKey::of(&fogged)));
    // A draw whose units are all incomplete textures nothing.
    let mut empty = state;
    empty.texturing = Some(Arc::new(Texturing { stages: Vec::new(), fb_height: 4 }));
    assert!(is_identity(&FragmentKey::of(&empty)));
}

/// Linear fog alone runs written out ([`LinearFog`]): the executor's bits on every lane, for
/// coordinates inside, outside and at the ends of the ramp, the edges (±0, ±∞, NaN, tiny)
/// and colours outside [0, 1], with start below, above and equal to end. A factor computed
/// another way (a reciprocal, a fused product, another clamp) differs in some lane.
#[test]
fn written_out_linear_fog_is_the_program_bit_for_bit() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    // Spans that are powers of two (1, 2⁻²³, 2, −0.25, 2⁻¹²⁷ subnormal, 2¹²⁷ with a
    // subnormal reciprocal) take the reciprocal's product, the others the division.
    let ends = [
        (0.0, 1.0),
        (0.2, 0.8),
        (0.8, 0.2),
        (-1.5, 3.25),
        (0.5, 0.5),
        (0.3, 0.3),
        (1.0, 1.0 + 1e-7),
        (-1.5, 0.5),
        (0.75, 0.5),
        (0.0, 2f32.powi(-127)),
        (0.0, 2f32.powi(127)),
    ];
    let edges = [0.0, -0.0, 1.0, -1.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 1e-38, 1e-45, 0.5, 0.2, 0.8];
    let mut checked = 0;
    for &(start, end) in &ends {
        let mut state = FragmentState::plain(None, Vec::new(), true);
        state.fog = Some(Fog { mode: FogMode::Linear, start, end, density: 1.0, color: [0.25, 0.6, 0.9, 1.0] });
        let shading = shading_of(&state);
        let fog = shading.linear_fog.expect("linear fog alone is written out");
        let span = (end - start).abs();
        let power_of_two = (span.is_normal() && span.to_bits() & 0x7f_ffff == 0)
            || (span.is_subnormal() && span.to_bits().is_power_of_two());
        let exact = power_of_two && (1.0 / span).is_finite();
        assert_eq!(matches!(fog.span, Some(Divisor::Reciprocal(_))), exact, "{start} {end}");
        for round in 0..200 {
            let coordinate: F32s = std::array::from_fn(|i| match round {
                0 => edges[i % edges.len()],
                1 => end + (i as f32 - 8.0) * 1e-7,
                _ => rng.unit() * 4.0 - 1.5,
            });
            let primary: [F32s; 4] = std::array::from_fn(|k| {
                std::array::from_fn(|i| {
                    if round == 0 && k == 0 {
                        edges[(i + 3) % edges.len()]
                    } else {
                        rng.unit() * 1.5 - 0.25
                    }
                })
            });
            let mut scratch = ShadingScratch::default();
            scratch.prepare(&shading);
            scratch.varyings[0] = coordinate;
            let mut want = primary;
            let textures = StageTextures { texturing: None, used: !0 };
            shading.run(&mut scratch, &textures, 0xffff, &mut want);
            // At every level the CPU has (each runs its own copy of the written-out fog).
            for level in crate::simd::Level::ALL.iter().filter_map(|&l| crate::simd::Supported::new(l)) {
                let mut got = primary;
                shading.run_block(level, &mut scratch, None, 0, 0xffff, &mut got, |_, first, out| {
                    assert_eq!((first, out.len()), (0, 1));
                    out[0] = coordinate;
                });
                for k in 0..4 {
                    for i in 0..LANES {
                        assert_eq!(
                            got[k][i].to_bits(),
                            want[k][i].to_bits(),
                            "start {start} end {end} c {} channel {k} {level:?}",
                            coordinate[i]
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    assert!(checked > 40_000);
    // Any other program keeps the executor.
    let mut state = FragmentState::plain(None, Vec::new(), true);
    state.fog = Some(Fog { mode: FogMode::Exp, start: 0.0, end: 1.0, density: 1.0, color: [0.0; 4] });
    assert!(shading_of(&state).linear_fog.is_none());
    state.fog = Some(Fog { mode: FogMode::Linear, start: 0.0, end: 1.0, density: 1.0, color: [0.0; 4] });
    state.color_sum = true;
    assert!(shading_of(&state).linear_fog.is_none());
}
