//! The frictionless normal problem (placeholder while the solver is written).
