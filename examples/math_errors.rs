//! Prints the measured error of tessera's transcendental functions against double precision
//! as a Markdown table (`tessera::shader::math::errors`): `tools/bench.sh` puts it into
//! BENCHMARKS.md. Run: `cargo run --release --example math_errors`.
fn main() {
    let rows = tessera::shader::math::errors::measure_all();
    print!("{}", tessera::shader::math::errors::markdown_table(&rows));
}
