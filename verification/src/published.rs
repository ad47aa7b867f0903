//! The published values of the three seeds, typed once, each with its source (seed, place,
//! the words it came from). Nothing computed lives here.
//!
//! Inputs that the seeds state (Table 1's parameters, the examples' loads) are here too, so
//! that every number taken from a seed has one home.

use crate::record::{Published, Resolution, Source};

const fn printed(
    text: &'static str,
    value: f64,
    place: &'static str,
    words: &'static str,
    seed: &'static str,
) -> Published {
    Published {
        text,
        value,
        resolution: Resolution::Printed,
        source: Source { seed, place, words },
    }
}

const fn digitised(
    text: &'static str,
    value: f64,
    err: f64,
    place: &'static str,
    words: &'static str,
    seed: &'static str,
) -> Published {
    Published {
        text,
        value,
        resolution: Resolution::Digitised(err),
        source: Source { seed, place, words },
    }
}

/// Seed 000: rigid roller on a power-law graded substrate.
pub mod seed000 {
    use super::{digitised, printed, Published};
    const S: &str = "000";
    const T1: &str = "Table 1";

    /// $\nu$ (Table 1, No. 1).
    pub const NU: Published = printed("0.3", 0.3, T1, "No. 1 v 0.3", S);
    /// $E_0$ in the table's "kg/m²" (kgf/m^2.1, FORMULAS.md A4) (Table 1, No. 2).
    pub const E0: Published = printed("1767600", 1767600.0, T1, "No. 2 E0 (kg/m2) 1767600", S);
    /// $I_k$ (Table 1, No. 3).
    pub const I_K: Published = printed("0.3489", 0.3489, T1, "No. 3 Ik 0.3489", S);
    /// $J_k$ (Table 1, No. 4).
    pub const J_K: Published = printed("0.3255", 0.3255, T1, "No. 4 Jk 0.3255", S);
    /// $\beta$ (Table 1, No. 5).
    pub const BETA: Published = printed("1.0261", 1.0261, T1, "No. 5 beta 1.0261", S);
    /// $k$ (Table 1, No. 6).
    pub const K: Published = printed("0.1", 0.1, T1, "No. 6 k 0.1", S);
    /// $h$ (Table 1, No. 7).
    pub const H: Published = printed("0.0053", 0.0053, T1, "No. 7 h (m) 0.0053", S);
    /// $a$ (Table 1, No. 8).
    pub const A: Published = printed("0.0178", 0.0178, T1, "No. 8 a (m) 0.0178", S);
    /// Friction coefficient (Table 1, No. 9).
    pub const F: Published = printed("1", 1.0, T1, "No. 9 f 1", S);
    /// $R$ (Table 1, No. 10).
    pub const R: Published = printed("0.3", 0.3, T1, "No. 10 R (m) 0.3", S);

    /// Digitising error of Table 2's coordinates (normalised units): the points were read by
    /// the authors off plotted curves; 0.05 is 5 % of the peak.
    pub const T2_READ: f64 = 0.05;

    /// Table 2, "Muskhelishvili's closed-form expression" row: $(x, y)$ of points 1–12.
    pub const T2_MUSKHELISHVILI: [(Published, Published); 12] = {
        const W: &str = "Muskhelishvili's closed-form expression X/Y";
        const P: &str = "Table 2";
        const E: f64 = T2_READ;
        [
            (digitised("-1", -1.0, E, P, W, S), digitised("0", 0.0, E, P, W, S)),
            (digitised("-0.85", -0.85, E, P, W, S), digitised("0.47", 0.47, E, P, W, S)),
            (digitised("-0.68", -0.68, E, P, W, S), digitised("0.7", 0.7, E, P, W, S)),
            (digitised("-0.5", -0.5, E, P, W, S), digitised("0.86", 0.86, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("1", 1.0, E, P, W, S)),
            (digitised("0.5", 0.5, E, P, W, S), digitised("0.875", 0.875, E, P, W, S)),
            (digitised("0.68", 0.68, E, P, W, S), digitised("0.71", 0.71, E, P, W, S)),
            (digitised("0.85", 0.85, E, P, W, S), digitised("0.49", 0.49, E, P, W, S)),
            (digitised("1", 1.0, E, P, W, S), digitised("0", 0.0, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.13", 0.13, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.3", 0.3, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.5", 0.5, E, P, W, S)),
        ]
    };

    /// Table 2, "Figure 7" row (the paper's own two-term curve): $(x, y)$ of points 1–12.
    pub const T2_FIGURE7: [(Published, Published); 12] = {
        const W: &str = "Figure 7 X/Y";
        const P: &str = "Table 2";
        const E: f64 = T2_READ;
        [
            (digitised("-1", -1.0, E, P, W, S), digitised("0", 0.0, E, P, W, S)),
            (digitised("-0.875", -0.875, E, P, W, S), digitised("0.41", 0.41, E, P, W, S)),
            (digitised("-0.72", -0.72, E, P, W, S), digitised("0.72", 0.72, E, P, W, S)),
            (digitised("-0.5", -0.5, E, P, W, S), digitised("0.93", 0.93, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("1", 1.0, E, P, W, S)),
            (digitised("0.5", 0.5, E, P, W, S), digitised("0.93", 0.93, E, P, W, S)),
            (digitised("0.72", 0.72, E, P, W, S), digitised("0.72", 0.72, E, P, W, S)),
            (digitised("0.875", 0.875, E, P, W, S), digitised("0.41", 0.41, E, P, W, S)),
            (digitised("1", 1.0, E, P, W, S), digitised("0", 0.0, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.25", 0.25, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.5", 0.5, E, P, W, S)),
            (digitised("0", 0.0, E, P, W, S), digitised("0.75", 0.75, E, P, W, S)),
        ]
    };

    /// Table 3's positions $x$ (m).
    pub const T3_X: [Published; 5] = {
        const P: &str = "Table 3";
        [
            printed("-0.0178", -0.0178, P, "X = - 0.0178", S),
            printed("-0.0100", -0.0100, P, "X = - 0.0100", S),
            printed("0.0000", 0.0, P, "X = 0.0000", S),
            printed("0.0100", 0.0100, P, "X = 0.0100", S),
            printed("0.0178", 0.0178, P, "X = 0.0178", S),
        ]
    };

    /// Table 3, "Giannakopoulos and Pallot's method" column at $\mu = 1$ (m).
    pub const T3_GP: [Published; 5] = {
        const P: &str = "Table 3";
        const W: &str = "Giannakopoulos and Pallot's method";
        [
            printed("0.0055", 0.0055, P, W, S),
            printed("0.0059", 0.0059, P, W, S),
            printed("0.0061", 0.0061, P, W, S),
            printed("0.0059", 0.0059, P, W, S),
            printed("0.0055", 0.0055, P, W, S),
        ]
    };

    /// Table 3, "The method that is used in this study" column at $\mu = 1$ (m).
    pub const T3_STUDY: [Published; 5] = {
        const P: &str = "Table 3";
        const W: &str = "The method that is used in this study";
        [
            printed("0.00225", 0.00225, P, W, S),
            printed("0.00220", 0.00220, P, W, S),
            printed("0.00190", 0.00190, P, W, S),
            printed("0.00170", 0.00170, P, W, S),
            printed("0.00140", 0.00140, P, W, S),
        ]
    };
}

/// Seed 002: traction and microslip (inputs lost in the OCR are in FORMULAS.md E, not here).
pub mod seed002 {
    use super::{digitised, printed, Published};
    const S: &str = "002";

    /// Example 1: sphere radius (in).
    pub const EX1_R: Published = printed("1", 1.0, "Example 1", "steel sphere of 1 in. radius", S);
    /// Example 1: normal load (lbf).
    pub const EX1_P: Published =
        printed("2160", 2160.0, "Example 1", "normal load is taken as 2160 lbf", S);
    /// Example 1: tangential load (lbf).
    pub const EX1_T: Published =
        printed("144", 144.0, "Example 1", "the tangential load is 144 lbf", S);
    /// Example 1: friction coefficient.
    pub const EX1_F: Published =
        printed("0.1", 0.1, "Example 1", "coefficient of friction is 0.1", S);
    /// Example 1: elements.
    pub const EX1_N: Published = printed("80", 80.0, "Example 1", "A grid with 80 elements", S);
    /// Example 1: LP rigid-body movement (in).
    pub const EX1_DELTA_LP: Published = printed(
        "0.66196e-4",
        0.66196e-4,
        "Example 1",
        "rigid body movement (0.66196 x 10-4 in.)",
        S,
    );
    /// Example 1: Mindlin's prediction (in).
    pub const EX1_DELTA_MINDLIN: Published = printed(
        "0.67139e-4",
        0.67139e-4,
        "Example 1",
        "Mindlin's prediction (0.67139 x 10-4 in.)",
        S,
    );
    /// Example 1: deviation LP vs Mindlin (%), printed without sign.
    pub const EX1_DEVIATION: Published =
        printed("1.41", 1.41, "Example 1", "a deviation of 1.41 %", S);
    /// Fig. 3.6: top of the traction axis (psi).
    pub const F36_AXIS_TOP: Published =
        digitised("35e3", 35e3, 2.5e3, "Fig. 3.6", "axis x 10^3: 35 30 25 ... 5 0", S);

    /// Example 2: normal load (lbf).
    pub const EX2_P: Published = printed("270", 270.0, "Example 2", "A normal load of 270 lbf", S);
    /// Example 2: tangential load (lbf).
    pub const EX2_T: Published = printed("36", 36.0, "Example 2", "a tangential load of 36 lbf", S);
    /// Example 2: friction coefficient.
    pub const EX2_F: Published =
        printed("0.2", 0.2, "Example 2", "a coefficient of friction of 0.2", S);
    /// Example 2: rubber movement (in).
    pub const EX2_DELTA_RUBBER: Published =
        printed("0.39469e-3", 0.39469e-3, "Example 2", "rubber half space (0.39469 x 10-3 in.)", S);
    /// Example 2: steel movement (in).
    pub const EX2_DELTA_STEEL: Published =
        printed("0.13156e-4", 0.13156e-4, "Example 2", "steel sphere (0.13156 x 10-4 in.)", S);
    /// Example 2: ratio rubber/steel.
    pub const EX2_RATIO: Published =
        printed("30", 30.0, "Example 2", "was found to be 30 times that of", S);
    /// Example 2: deviation from Mindlin (%), printed without sign.
    pub const EX2_DEVIATION: Published = printed(
        "2.29",
        2.29,
        "Example 2",
        "agree well with Mindlin's prediction with a 2.29% deviation",
        S,
    );

    /// Table 3.1: ellipse ratio $a/b$ and number of grid elements.
    pub const T31: [(Published, Published); 4] = {
        const P: &str = "Table 3.1";
        [
            (printed("2.0", 2.0, P, "a/b = 2.0", S), printed("112", 112.0, P, "112 Fig. 3.8", S)),
            (printed("0.5", 0.5, P, "a/b = 0.5", S), printed("112", 112.0, P, "112 Fig. 3.9", S)),
            (printed("8.0", 8.0, P, "a/b = 8.0", S), printed("116", 116.0, P, "116 Fig. 3.10", S)),
            (
                printed("0.125", 0.125, P, "a/b = 0.125", S),
                printed("116", 116.0, P, "116 Fig. 3.11", S),
            ),
        ]
    };

    /// Example 4: square side (in), FORMULAS.md/VERIFICATION.md's reading.
    pub const EX4_PRESSURE: Published =
        printed("10,000", 10_000.0, "Example 4", "uniform contact pressure of 10,000 psi", S);
    /// Example 4: friction.
    pub const EX4_F: Published =
        printed("0.12", 0.12, "Example 4", "coefficient of friction, f = 0.12", S);
    /// Example 4: elements.
    pub const EX4_N: Published =
        printed("100", 100.0, "Example 4", "discretized with 100 square grid elements", S);
    /// Fig. 3.12 (T = 800 lbf): lowest contour label (psi).
    pub const F312_LOWEST: Published =
        digitised("430", 430.0, 0.5, "Fig. 3.12", "+ 430 psi (lowest label)", S);
    /// Fig. 3.12 (T = 800 lbf): highest contour label (psi).
    pub const F312_HIGHEST: Published =
        digitised("1200", 1200.0, 0.5, "Fig. 3.12", "... 1125 1200 (highest label)", S);
    /// Fig. 3.13 (T = 1000 lbf): lowest contour label (psi), OCR "s30p.i".
    pub const F313_LOWEST: Published =
        digitised("530", 530.0, 0.5, "Fig. 3.13", "+ s30p.i (lowest label)", S);
    /// Fig. 3.15: top of the load axis, gross slip (lbf).
    pub const F315_GROSS: Published =
        digitised("1.2e3", 1200.0, 50.0, "Fig. 3.15", "load axis 0.0 ... 1.2 (x 10^3 lbf)", S);
    /// Fig. 3.15: end of the movement axis (in).
    pub const F315_MOVEMENT_AXIS: Published = digitised(
        "5e-5",
        5e-5,
        0.5e-5,
        "Fig. 3.15",
        "Rigid Body Movement (x 10-5 in.) 0 1 2 3 4 5",
        S,
    );

    /// Example 5: square side (in).
    pub const EX5_SIDE: Published =
        printed("0.6", 0.6, "Example 5", "same size (0.6in. x 0.6in)", S);
    /// Example 5: centroid distance (in).
    pub const EX5_DISTANCE: Published =
        printed("1.0", 1.0, "Example 5", "centroids of the two squares are placed 1.0in. apart", S);
    /// Example 5: region 2 full slip (lbf), case 2/3 pressures.
    pub const EX5_REGION2_FULL_SLIP: Published = printed(
        "1000",
        1000.0,
        "Example 5, Fig. 3.20",
        "region 2 reached the condition of full slip at a load of 1000 lbf",
        S,
    );
    /// Example 5: gross slip (lbf).
    pub const EX5_GROSS_SLIP: Published = printed(
        "1296",
        1296.0,
        "Example 5, Fig. 3.20",
        "gross slip occurred for the total contact at 1296 lbf",
        S,
    );
}
