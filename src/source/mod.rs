//! Flexibility sources: what turns a scene's bodies into the contact flexibility ([`crate::flexibility`]).
//!
//! Two sources: the boundary-element model of the finite wheel ([`bem_wheel`], `[wheel] model = "bem"`) and the
//! elastic half-plane with the wheel's gap (`half_plane`, `model = "half_plane"`); either may meet an elastic
//! counter-body (`half_plane::add_counter_body`). A source builds only the blocks a scene needs ([`Blocks`]): a
//! frictionless scene gets the normal columns only. It reports what it is made of ([`SourceInfo`]) for the result
//! document and the health line.

pub mod bem_wheel;
pub(crate) mod half_plane;
pub mod two_body;

use crate::error::Result;
use crate::flexibility::Flexibility;
use crate::scene::{ElementKind, Scene};

/// Which blocks of the flexibility to compute.
/// Ordered: a model with more blocks serves every scene that needs fewer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Blocks {
    /// Only K_NN and the normal rigid responses: the frictionless problem.
    Normal,
    /// K_NN, K_TT and both rigid responses: friction or rolling without normal–tangential coupling (the half-plane
    /// model leaves out K_NT and K_TN, two n × n blocks; a BEM wheel's condensation yields them anyway and keeps
    /// them).
    Uncoupled,
    /// K_NN, K_NT, K_TN, K_TT and both rigid responses.
    All,
}

/// What a source is made of, and its numerical health (the BEM figures are `None` for closed-form sources).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct SourceInfo {
    /// Number of boundary elements.
    pub elements: usize,
    /// Number of nodes (collocation points).
    pub nodes: usize,
    /// Element family.
    pub element: ElementKind,
    /// Size of the rearranged BEM system (2 × nodes), when there is one.
    pub system_size: Option<usize>,
    /// Largest/smallest |U_ii| of the BEM system's LU (a lower bound of its condition number).
    pub pivot_ratio: Option<f64>,
    /// Estimated 1-norm condition number of the rearranged BEM system.
    pub condition: Option<f64>,
    /// Smallest contact element length (user's unit).
    pub contact_element_length: f64,
    /// Whether a body is viscoelastic ([`crate::viscoelastic`]): its memory makes the flexibility nonsymmetric.
    pub viscoelastic: bool,
}

/// Wall-clock time of a source's two stages, seconds.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
#[non_exhaustive]
pub struct SourceTiming {
    /// Assembly (BEM: H and G into the rearranged system).
    pub assembly: f64,
    /// Condensation (BEM: one LU and the solves for F).
    pub condensation: f64,
}

/// A built flexibility with its description and timings.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct Built {
    /// The flexibility.
    pub flex: Flexibility,
    /// What it is made of.
    pub info: SourceInfo,
    /// Time per stage.
    pub timing: SourceTiming,
    /// The BEM wheel's whole boundary response to unit contact tractions, kept only when the scene asks for
    /// interior stresses (`[stresses]`); `None` otherwise and for closed-form sources.
    pub boundary: Option<bem_wheel::BoundaryResponse>,
    /// Two finite bodies with `[stresses]`: the counter-body's boundary response and the pair's frames
    /// ([`two_body::PairResponse`]); `None` otherwise.
    pub pair: Option<two_body::PairResponse>,
}

/// Build the flexibility a (validated) scene describes, with the blocks it needs.
pub fn build(scene: &Scene, blocks: Blocks) -> Result<Built> {
    let Some((support, spec)) = crate::mesh::MeshSpec::of_scene(scene) else {
        let n = scene.zone().elements;
        let _stage = crate::progress::stage(|| format!("building the half-plane influence matrices ({n} elements)"));
        return half_plane::build(scene, blocks);
    };
    if let Some((counter, other)) = two_body::counter_of(scene.counter_body()) {
        let bodies = two_body::TwoBodies::new(*scene.wheel(), support, spec, counter, other);
        return two_body::build_with(&bodies, blocks, scene.stresses().is_some());
    }
    let model = bem_wheel::Model::new(scene.wheel(), support, &spec)?;
    let (mut flex, health, t, response) = bem_wheel::condense_with_response(&model, blocks)?;
    half_plane::add_counter_body(&mut flex, scene, &half_plane::Grid::of(scene))?;
    let mesh = &model.mesh;
    let (elements, nodes, element) = (mesh.elements.len(), mesh.n_nodes(), mesh.kind);
    let boundary = scene.stresses().is_some().then(|| bem_wheel::BoundaryResponse {
        tangential: blocks != Blocks::Normal,
        matrix: response,
        model,
    });
    Ok(Built {
        info: SourceInfo {
            elements,
            nodes,
            element,
            system_size: Some(health.system_size),
            pivot_ratio: Some(health.pivot_ratio),
            condition: Some(health.system_condition),
            contact_element_length: scene.zone().element_length(scene.radius()),
            viscoelastic: false,
        },
        flex,
        timing: SourceTiming { assembly: t.assembly, condensation: t.condensation },
        boundary,
        pair: None,
    })
}
