//! Jobs: set-up primitives with everything their fragments need (edges or coverage,
//! bounds, attribute planes), one module per primitive kind, and how each renders inside
//! one tile: its coverage walked by `raster`'s walkers, each covered span handed with its
//! depth, colors and varyings to `fragment`'s pipeline. The scene bins them; the tile
//! workers call their `render`.

pub mod clear;
pub mod line;
pub mod pixels;
pub mod point;
pub mod smooth;
pub mod triangle;
