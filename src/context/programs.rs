//! The compiled fixed-function programs of a share group: the vertex and fragment programs
//! the draws' states generate, each kind in a [`ProgramCache`] keyed by the state's compact
//! key, so that a context finds a program any context of its group compiled before.
//!
//! Every draw looks its programs up here (once per draw state; the vertex stage once per run
//! of vertices between glMaterial calls): the generated programs are the only vertex
//! processing and fragment shading there is.
//!
//! Under `TESSERA_DEBUG=programs` every program generated on a miss is printed on stderr in
//! the text form of [`crate::shader::dump`], after a line naming its kind and the cache's
//! counts; every GLSL program's stages are printed the same way when it is linked
//! ([`print_linked`]).
use super::debug;
use crate::fragment::program::{CompiledFragment, FragmentKey};
use crate::shader::cache::{CacheStats, ProgramCache};
use crate::shader::dump::dump;
use crate::vertex::program::{CompiledVertex, VertexKey};
use std::sync::Arc;

/// The program caches of one share group.
#[derive(Default)]
pub struct ProgramCaches {
    vertex: ProgramCache<VertexKey, CompiledVertex>,
    fragment: ProgramCache<FragmentKey, CompiledFragment>,
}

impl ProgramCaches {
    /// The vertex program of `key`, generated on a miss.
    pub fn vertex(&mut self, key: &VertexKey) -> Arc<CompiledVertex> {
        let stats = self.vertex.stats();
        self.vertex.get_or_generate(key, |key| {
            let generated = CompiledVertex::generate(key);
            print_generated("vertex", stats, || dump(&generated.generated.program));
            generated
        })
    }

    /// The fragment program of `key`, generated on a miss.
    pub fn fragment(&mut self, key: &FragmentKey) -> Arc<CompiledFragment> {
        let stats = self.fragment.stats();
        self.fragment.get_or_generate(key, |key| {
            let generated = CompiledFragment::generate(key);
            print_generated("fragment", stats, || dump(&generated.fixed.program));
            generated
        })
    }

    /// What each cache has done: (vertex, fragment).
    pub fn stats(&self) -> (CacheStats, CacheStats) {
        (self.vertex.stats(), self.fragment.stats())
    }
}

fn print_generated(kind: &str, before: CacheStats, text: impl FnOnce() -> String) {
    if debug::enabled("programs") {
        eprintln!(
            "tessera programs: {kind} program generated (cache: {} hits, {} misses before this one, {} evicted)",
            before.hits, before.misses, before.evictions
        );
        eprintln!("{}", text());
    }
}

/// Under `TESSERA_DEBUG=programs`, prints a GLSL program's `stage` as linked (once per
/// successful link: the IR the draws run, before the executor's own lowering).
pub fn print_linked(stage: crate::glsl::Stage, program: &crate::shader::ir::Program) {
    if debug::enabled("programs") {
        eprintln!("{}", linked_text(stage, program));
    }
}

/// What [`print_linked`] prints: a line naming the stage, then the program's text form.
fn linked_text(stage: crate::glsl::Stage, program: &crate::shader::ir::Program) -> String {
    let kind = match stage {
        crate::glsl::Stage::Vertex => "vertex",
        crate::glsl::Stage::Fragment => "fragment",
    };
    format!("tessera programs: GLSL {kind} program linked\n{}", dump(program))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::program::FogKey;

    #[test]
    fn a_linked_glsl_stage_prints_its_kind_then_its_text() {
        use crate::shader::ir::{Const, Inst, Program, Stage, Stmt, Type};
        let mut program = Program::new(Stage::Fragment);
        let r = program.register(Type::F32);
        let slot = program.output(Type::F32);
        program.body = vec![
            Stmt::Inst(Inst::Const { dst: r, value: Const::F32(0.25) }),
            Stmt::Inst(Inst::Output { slot, src: r }),
        ];
        let text = linked_text(crate::glsl::Stage::Fragment, &program);
        assert!(
            text.starts_with("tessera programs: GLSL fragment program linked\nfragment program: 1 registers"),
            "{text}"
        );
        assert!(text.contains("output 0 = r0"), "{text}");
    }

    #[test]
    fn a_fragment_key_seen_before_is_not_generated_again() {
        let mut caches = ProgramCaches::default();
        let key = FragmentKey { stages: Vec::new(), color_sum: Some(true), fog: Some(FogKey::Linear) };
        let a = caches.fragment(&key);
        let b = caches.fragment(&key);
        assert!(Arc::ptr_eq(&a, &b));
        let other = FragmentKey { fog: None, ..key };
        let c = caches.fragment(&other);
        assert!(!Arc::ptr_eq(&a, &c));
        assert_eq!(caches.stats().1.misses, 2);
        assert_eq!(caches.stats().1.hits, 1);
    }
}
