//! Result documents as CSV tables: the nodal table (`rollbem run --csv`) and a load path's table
//! (`rollbem run --path-csv`), in the user's units.

use super::Report;

impl Report {
    /// The nodal table as CSV (`rollbem run --csv`): one row per contact node and solver run that has nodes (a run
    /// that did not solve has none, except the evidence kept by a run judged `contact_at_zone_edge` or
    /// `kinematics_out_of_range`: the `status` column tells them apart), with the keys of `runs[].nodes[]` in the user's units; empty cells where a
    /// value is null (u_x without the tangential problem, the slip of a separated node, the slip velocity without
    /// rolling).
    pub fn nodes_csv(&self) -> String {
        // No cell needs quoting: solver names are registry names (letters, digits, `_`), statuses and states are
        // names, the numbers are written by `{:e}`.
        let mut out = String::new();
        let mut record = |cells: &[&str]| {
            out.push_str(&cells.join(","));
            out.push('\n');
        };
        let head = [
            "solver",
            "status",
            "node",
            "x",
            "y",
            "pressure",
            "shear",
            "u_x",
            "u_y",
            "gap",
            "slip",
            "state",
            "slip_velocity",
        ];
        record(&head);
        let opt = |v: Option<f64>| v.map(|v| format!("{v:e}")).unwrap_or_default();
        for run in &self.runs {
            for (i, n) in run.nodes.iter().enumerate() {
                let cells = [
                    run.solver.to_string(),
                    run.status.name().to_string(),
                    i.to_string(),
                    format!("{:e}", n.x),
                    format!("{:e}", n.y),
                    format!("{:e}", n.pressure),
                    format!("{:e}", n.shear),
                    opt(n.u_x),
                    format!("{:e}", n.u_y),
                    format!("{:e}", n.gap),
                    opt(n.slip),
                    n.state.name().to_string(),
                    opt(n.slip_velocity),
                ];
                record(&cells.each_ref().map(String::as_str));
            }
        }
        out
    }

    /// The path as CSV: one row per substep and solver (a solver whose path broke earlier has no row), in the user's
    /// units. Columns: where on the path (`step`, `substep`, `substeps`, `rolled`), the solver and its status, the
    /// resultants (`Q`, `P`, `M`), the rigid motion (`shift`, `approach`, `rotation`; `shift` empty when indeterminate at
    /// the sliding limit), the stick zone (`stick_left`, `stick_right`: midway between the outermost sticking node and
    /// its neighbour, empty when nothing sticks), node counts per state, the dissipated energy of the substep and since
    /// the start of the path (energy per unit thickness), the largest residual and the solve time in seconds.
    pub fn path_csv(&self) -> String {
        use std::fmt::Write as _;
        let mut out = String::from(
            "step,substep,substeps,rolled,solver,status,Q,P,M,shift,approach,rotation,stick_left,stick_right,\
             nodes_stick,nodes_slip,nodes_separated,dissipated,dissipated_total,residual,t_solve\n",
        );
        // `+ 0.0` prints −0 as 0.
        let opt = |v: Option<f64>| v.map(|v| format!("{:e}", v + 0.0)).unwrap_or_default();
        for st in &self.steps {
            for run in &st.runs {
                let f = run.resultants;
                let rb = run.rigid_body;
                // A substep judged not an answer keeps its nodes as evidence; its row reports no stick zone or counts.
                let nodes = run.answer_nodes();
                let edges = crate::post::stick_edges(nodes);
                let count = |s: crate::post::NodeState| nodes.iter().filter(|n| n.state == s).count();
                let e = run.history.as_ref();
                writeln!(
                    out,
                    "{},{},{},{:e},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:e}",
                    st.step,
                    st.substep,
                    st.substeps,
                    st.rolled,
                    run.solver,
                    run.status,
                    opt(f.map(|f| f.tangential)),
                    opt(f.map(|f| f.normal)),
                    opt(f.map(|f| f.moment)),
                    opt(rb.and_then(|r| r.tangential)),
                    opt(rb.map(|r| r.normal)),
                    opt(rb.map(|r| r.rotation)),
                    opt(edges.map(|e| e.0)),
                    opt(edges.map(|e| e.1)),
                    count(crate::post::NodeState::Stick),
                    count(crate::post::NodeState::Slip),
                    count(crate::post::NodeState::Separated),
                    opt(e.map(|e| e.dissipated)),
                    opt(e.map(|e| e.dissipated_total)),
                    opt(run.residuals.map(|r| r.max())),
                    run.timing_s.solve
                )
                .expect("writing to a String");
            }
        }
        out
    }
}
