//! Quadrature rules: Gauss–Legendre on [−1, 1] and Gauss rules for the weight −ln(t) on [0, 1].
//!
//! Gauss–Legendre rules are computed at run time (Newton iteration on the Legendre polynomials) and cached
//! by `gl`. The logarithmic rules are hard-coded tables for n = 1..=`LOG_GAUSS_MAX`, generated to full
//! double precision by `reference/tools/log_gauss.py` (exact rational recurrence coefficients from the moments
//! ∫₀¹ −ln(t) tᵏ dt = 1/(k+1)², Golub–Welsch eigen-decomposition at 80 digits with mpmath). To regenerate:
//! `python3 reference/tools/log_gauss.py 20 > /tmp/t.rs` and paste the two tables over the
//! `LOG_GAUSS_NODES` / `LOG_GAUSS_WEIGHTS` constants in this file (then `rustfmt --edition 2021` it).

use crate::error::ArgumentError;
use std::sync::OnceLock;

/// A quadrature rule: abscissae `points` and matching `weights` (same length), on the interval documented by the
/// function that produced it.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub struct Rule {
    /// Abscissae, in increasing order.
    pub points: Vec<f64>,
    /// Weights, one per abscissa.
    pub weights: Vec<f64>,
}

impl Rule {
    /// Number of points of the rule.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// True if the rule has no points.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Iterator over `(point, weight)` pairs.
    pub fn iter(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.points.iter().copied().zip(self.weights.iter().copied())
    }
}

/// n-point Gauss–Legendre rule on [−1, 1] (exact for polynomials of degree < 2n), any n ≥ 1 (`n = 0` is refused).
///
/// Nodes by Newton iteration on Pₙ from Tricomi's initial guesses, weights 2 / ((1 − x²) Pₙ′(x)²); accurate to
/// a few ulp. Allocates (the crate's hot loops use a cache of these rules).
pub fn gauss_legendre(n: usize) -> Result<Rule, ArgumentError> {
    if n == 0 {
        return Err(ArgumentError::new("gauss_legendre", "n", "must be at least 1 (the number of points)"));
    }
    Ok(legendre_rule(n))
}

/// [`gauss_legendre`] for n ≥ 1.
fn legendre_rule(n: usize) -> Rule {
    let nf = n as f64;
    let mut points = vec![0.0; n];
    let mut weights = vec![0.0; n];
    let m = n.div_ceil(2);
    for i in 0..m {
        // Tricomi's approximation of the i-th largest root.
        let th = std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5);
        let mut x = (1.0 - (nf - 1.0) / (8.0 * nf * nf * nf)) * th.cos();
        for _ in 0..100 {
            let (p, d) = legendre_and_derivative(n, x);
            let dx = p / d;
            x -= dx;
            if dx.abs() <= 1e-16 * x.abs().max(1e-3) {
                break;
            }
        }
        // Weight at the rounded node x̃ = x* + δ, corrected to first order towards the exact node x*:
        // d ln w / dx = 2x / (1 − x²) at a root of Pₙ, and δ = Pₙ(x̃)/Pₙ′(x̃). Without the correction the end
        // weights lose ~2 digits (1 − x² amplifies the node's rounding error).
        let (p, dp) = legendre_and_derivative(n, x);
        let delta = p / dp;
        let one_m_x2 = (1.0 - x) * (1.0 + x);
        let w = 2.0 / (one_m_x2 * dp * dp) * (1.0 + 2.0 * x * delta / one_m_x2);
        points[i] = -x;
        points[n - 1 - i] = x;
        weights[i] = w;
        weights[n - 1 - i] = w;
    }
    if n % 2 == 1 {
        points[n / 2] = 0.0;
    }
    Rule { points, weights }
}

/// Pₙ(x) and Pₙ′(x) by the three-term recurrence (|x| < 1), carried in double-double arithmetic so that the
/// weights keep full precision near the ends of the interval (the plain f64 recurrence loses ~2 digits there).
fn legendre_and_derivative(n: usize, x: f64) -> (f64, f64) {
    if n == 0 {
        return (1.0, 0.0);
    }
    let xd = Dd::from(x);
    let mut p0 = Dd::from(1.0);
    let mut p1 = xd;
    for k in 2..=n {
        let kf = k as f64;
        let p2 = (p1.mul(xd).mul_f(2.0 * kf - 1.0).sub(p0.mul_f(kf - 1.0))).div_f(kf);
        p0 = p1;
        p1 = p2;
    }
    // (x² − 1) = (x − 1)(x + 1), both factors exact in f64 except the rounding of x + 1, kept in dd.
    let x2m1 = Dd::two_sum(x, -1.0).mul(Dd::two_sum(x, 1.0));
    let d = p1.mul(xd).sub(p0).mul_f(n as f64).div(x2m1);
    (p1.hi + p1.lo, d.hi + d.lo)
}

/// Minimal double-double number (hi + lo, |lo| ≤ ulp(hi)/2), only for computing Gauss–Legendre rules.
#[derive(Debug, Clone, Copy)]
struct Dd {
    hi: f64,
    lo: f64,
}

impl Dd {
    fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }
    fn two_sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        let bb = s - a;
        let e = (a - (s - bb)) + (b - bb);
        Dd { hi: s, lo: e }
    }
    fn quick(a: f64, b: f64) -> Dd {
        let s = a + b;
        Dd { hi: s, lo: b - (s - a) }
    }
    fn add(self, o: Dd) -> Dd {
        let s = Dd::two_sum(self.hi, o.hi);
        Dd::quick(s.hi, s.lo + self.lo + o.lo)
    }
    fn sub(self, o: Dd) -> Dd {
        self.add(Dd { hi: -o.hi, lo: -o.lo })
    }
    fn mul(self, o: Dd) -> Dd {
        let p = self.hi * o.hi;
        let e = self.hi.mul_add(o.hi, -p);
        Dd::quick(p, e + self.hi * o.lo + self.lo * o.hi)
    }
    fn mul_f(self, f: f64) -> Dd {
        self.mul(Dd::from(f))
    }
    fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul_f(q1));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul_f(q2));
        let q3 = r.hi / o.hi;
        Dd::quick(q1, q2).add(Dd::from(q3))
    }
    fn div_f(self, f: f64) -> Dd {
        self.div(Dd::from(f))
    }
}

/// Largest n of the tabulated logarithmic rules ([`log_gauss`], [`lg`]).
pub(crate) const LOG_GAUSS_MAX: usize = 20;

/// n-point Gauss rule for the weight −ln(t) on [0, 1]: ∫₀¹ −ln(t) f(t) dt ≈ Σ wᵢ f(tᵢ), exact for polynomials of
/// degree < 2n. Tabulated for 1 ≤ n ≤ [`LOG_GAUSS_MAX`]. Allocates: in hot loops use the cached [`lg`].
///
/// An internal rule: the crate asks only for tabulated orders (`n == 0` or `n > LOG_GAUSS_MAX` would panic).
pub(crate) fn log_gauss(n: usize) -> Rule {
    assert!((1..=LOG_GAUSS_MAX).contains(&n), "log_gauss: n = {n} outside the tabulated range 1..={LOG_GAUSS_MAX}");
    Rule { points: LOG_GAUSS_NODES[n - 1].to_vec(), weights: LOG_GAUSS_WEIGHTS[n - 1].to_vec() }
}

/// Largest n cached by [`gl`].
pub(crate) const GL_CACHE_MAX: usize = 64;

static GL_CACHE: [OnceLock<Rule>; GL_CACHE_MAX] = [const { OnceLock::new() }; GL_CACHE_MAX];
static LG_CACHE: [OnceLock<Rule>; LOG_GAUSS_MAX] = [const { OnceLock::new() }; LOG_GAUSS_MAX];

/// Cached n-point Gauss–Legendre rule on [−1, 1] (see [`gauss_legendre`]); computed once per n, thread-safe. An
/// internal cache: the crate asks only for orders 1..=[`GL_CACHE_MAX`] (another would panic).
pub(crate) fn gl(n: usize) -> &'static Rule {
    assert!((1..=GL_CACHE_MAX).contains(&n), "gl: n = {n} outside 1..={GL_CACHE_MAX}");
    GL_CACHE[n - 1].get_or_init(|| legendre_rule(n))
}

/// Cached n-point logarithmic Gauss rule on [0, 1] (see [`log_gauss`]); internal as [`gl`].
pub(crate) fn lg(n: usize) -> &'static Rule {
    assert!((1..=LOG_GAUSS_MAX).contains(&n), "lg: n = {n} outside 1..={LOG_GAUSS_MAX}");
    LG_CACHE[n - 1].get_or_init(|| log_gauss(n))
}

// Generated by reference/tools/log_gauss.py 20 (do not edit by hand).
const LOG_GAUSS_NODES: [&[f64]; 20] = [
    &[0.25],
    &[0.11200880616697619, 0.6022769081187381],
    &[0.0638907930873254, 0.36899706371561874, 0.7668803039389415],
    &[0.04144848019938322, 0.24527491432060225, 0.5561654535602758, 0.8489823945329852],
    &[0.029134472151972055, 0.17397721332089763, 0.41170252028490206, 0.6773141745828204, 0.8947713610310083],
    &[
        0.021634005844116948,
        0.1295833911549508,
        0.3140204499147655,
        0.5386572173518022,
        0.7569153373774028,
        0.9226688513721203,
    ],
    &[
        0.016719355408258516,
        0.10018567791567512,
        0.2462942462079306,
        0.4334634932570331,
        0.6323509880477661,
        0.8111186267401056,
        0.9408481667433477,
    ],
    &[
        0.013320244160892464,
        0.07975042901389494,
        0.19787102932618805,
        0.3541539943519094,
        0.5294585752349172,
        0.7018145299391,
        0.8493793204411066,
        0.9533264500563597,
    ],
    &[
        0.010869336084175478,
        0.06498366633800794,
        0.16222939802388295,
        0.29374990397167466,
        0.44663188190546804,
        0.6054816627761286,
        0.7541101371571636,
        0.8772658288358383,
        0.9622505594102818,
    ],
    &[
        0.009042630962199651,
        0.05397126622250063,
        0.1353118246392508,
        0.24705241628715982,
        0.3802125396093323,
        0.5237923179718432,
        0.6657752055164246,
        0.7941904160119663,
        0.8981610912190036,
        0.9688479887186335,
    ],
    &[
        0.007643941174637707,
        0.04554182825657892,
        0.11452229745512459,
        0.21037858122703354,
        0.32669555322169286,
        0.45545324692881345,
        0.5876483563590844,
        0.7139638500125615,
        0.8254532178018118,
        0.9141939216125431,
        0.9738602562755861,
    ],
    &[
        0.006548722279080058,
        0.038946809560449956,
        0.09815026310600664,
        0.18113858159063156,
        0.28322006766737257,
        0.39843443516343663,
        0.5199526267923527,
        0.6405109167161065,
        0.7528650120518305,
        0.8502400241623022,
        0.9267496832239142,
        0.9777561296899975,
    ],
    &[
        0.005674766256242669,
        0.03369010879903254,
        0.08503675447417502,
        0.15749755947788902,
        0.24756957887684314,
        0.3507443123608552,
        0.46177374676161026,
        0.5749594665255613,
        0.68445988035043,
        0.7846025688103471,
        0.8701864284078884,
        0.9367578293067514,
        0.9808434518115909,
    ],
    &[
        0.004966003573868542,
        0.02943254011888518,
        0.07437629222453576,
        0.1381384919891863,
        0.2180556484989591,
        0.31066208391810196,
        0.4118724751777502,
        0.5171793073986544,
        0.6218648597285111,
        0.7212207452081089,
        0.8107659880715898,
        0.8864540380344347,
        0.9448591394618187,
        0.9833310264856785,
    ],
    &[
        0.004383110175475404,
        0.025935898105330615,
        0.06559609541231624,
        0.1221019340733316,
        0.19339526237400712,
        0.27677283870610203,
        0.36901512713974294,
        0.4665243289647066,
        0.5654734737918173,
        0.6619629190124564,
        0.7521788833787858,
        0.8325480338661896,
        0.8998820501208981,
        0.9515061887434099,
        0.985364468122132,
    ],
    &[
        0.003897834487115916,
        0.02302894561687324,
        0.05828039830624041,
        0.10867836509105404,
        0.17260945490984395,
        0.24793705447057848,
        0.33209454912991715,
        0.4221839105819486,
        0.5150824733814626,
        0.6075561204477288,
        0.696375653228214,
        0.7784325658732654,
        0.8508502697153911,
        0.9110868572222719,
        0.9570255717035422,
        0.9870478002479844,
    ],
    &[
        0.0034894494280936494,
        0.020586040687761077,
        0.052121791629722344,
        0.0973354259275744,
        0.15494585798324947,
        0.2232439542054496,
        0.30016159887346433,
        0.3833435195305404,
        0.47022507319960094,
        0.5581152770264924,
        0.6442831517315017,
        0.7260449608388133,
        0.8008497372797015,
        0.8663604605788398,
        0.9205283193035555,
        0.961657532071674,
        0.9884569188474353,
    ],
    &[
        0.003142465138001453,
        0.018513312208084286,
        0.04688918299535677,
        0.08766817917797515,
        0.13982127438539052,
        0.20196630657019948,
        0.27242025550071136,
        0.3492525386626254,
        0.4303425885591433,
        0.5134416004393164,
        0.5962373085195326,
        0.6764202326322136,
        0.7517496550418376,
        0.8201175269058244,
        0.8796085228931839,
        0.9285545288298973,
        0.9655818519928323,
        0.9896482384971661,
    ],
    &[
        0.002845114727580032,
        0.016739486860234087,
        0.04240623331212135,
        0.0793646495242485,
        0.12677952471324475,
        0.18352196537481588,
        0.24820975153899896,
        0.3192475608580212,
        0.3948702260858033,
        0.4731892560509978,
        0.5522419668622571,
        0.6300422144456346,
        0.7046315560242424,
        0.7741295987147355,
        0.8367822829052873,
        0.8910068794580738,
        0.9354325324726562,
        0.9689351591597295,
        0.9906643927886234,
    ],
    &[
        0.0025883279559219554,
        0.015209662349560232,
        0.03853655037216533,
        0.0721816138158739,
        0.11546052648763315,
        0.16744285627532968,
        0.2269837872602025,
        0.29275496094154585,
        0.3632774298578589,
        0.4369571400907683,
        0.5121225946789674,
        0.5870640449144099,
        0.6600734133149094,
        0.7294840839296874,
        0.7937096719870859,
        0.8512808927891258,
        0.9008796808544176,
        0.9413697491290917,
        0.9718227410752632,
        0.991538081438712,
    ],
];
const LOG_GAUSS_WEIGHTS: [&[f64]; 20] = [
    &[1.0],
    &[0.7185393190303845, 0.2814606809696156],
    &[0.5134045522323634, 0.39198004120148755, 0.09461540656614913],
    &[0.3834640681451351, 0.38687531777476264, 0.19043512695014242, 0.03922548712995983],
    &[0.29789347178289444, 0.34977622651322415, 0.23448829004405242, 0.09893045951663315, 0.018911552143195797],
    &[
        0.23876366257854756,
        0.3082865732739468,
        0.24531742656321037,
        0.14200875656647668,
        0.05545462232488629,
        0.010168958692932276,
    ],
    &[
        0.1961693894252482,
        0.27030264424727296,
        0.23968187300769095,
        0.1657757748104329,
        0.08894322713765797,
        0.033194304356571065,
        0.005932787015125924,
    ],
    &[
        0.16441660472800287,
        0.23752561002330602,
        0.22684198443191914,
        0.17575407900607024,
        0.11292403024675905,
        0.05787221071778207,
        0.020979073742132977,
        0.003686407104027619,
    ],
    &[
        0.14006843874813474,
        0.20977220520103046,
        0.21142714989660272,
        0.17715623393808,
        0.1277992280332055,
        0.07847890261156218,
        0.039022504985399095,
        0.013867295549593024,
        0.0024080410363923116,
    ],
    &[
        0.12095513195457051,
        0.18636354256407187,
        0.19566087327776,
        0.17357714218290693,
        0.1356956729954842,
        0.09364675853811052,
        0.05578772735141587,
        0.02715981089923333,
        0.009515182602848515,
        0.0016381576335982632,
    ],
    &[
        0.10565225609910049,
        0.16657168060062905,
        0.18056321828775374,
        0.1672787367737842,
        0.1386970574016312,
        0.10383343336504407,
        0.06953669788873523,
        0.04054160080359633,
        0.019435402476218173,
        0.006737429342450063,
        0.0011524869610574778,
    ],
    &[
        0.09319269144393133,
        0.14975182757632235,
        0.16655745436459302,
        0.15963355943698765,
        0.13842483186483562,
        0.11001657063572116,
        0.07996182177082897,
        0.05240695482464177,
        0.030071088873761188,
        0.01424924558799828,
        0.004899924582321761,
        0.0008340290380569034,
    ],
    &[
        0.08290049679327578,
        0.1353686731657445,
        0.1537732843922922,
        0.1514581585099882,
        0.13604033653728306,
        0.1131768228816338,
        0.08737443048004526,
        0.06216023064180487,
        0.04008772893416585,
        0.022723844939972194,
        0.010671230412968444,
        0.00364649227597414,
        0.000618270034851697,
    ],
    &[
        0.07429122506751042,
        0.12298877246932291,
        0.14219930656252336,
        0.1432292976412642,
        0.1323450837720852,
        0.11413587573667648,
        0.0922830380790736,
        0.06975367329393757,
        0.048830323600513564,
        0.03110179606441614,
        0.017462811950196094,
        0.008142423429875936,
        0.0027684364185639374,
        0.00046793591404056014,
    ],
    &[
        0.06700997891649371,
        0.11226415028670574,
        0.1317601770396799,
        0.13521764906193473,
        0.12788179864568036,
        0.11353290749021942,
        0.09520523978435866,
        0.07538931416739596,
        0.05607842449265372,
        0.03876829537501823,
        0.024451483268750077,
        0.013624630138238846,
        0.006316447598590761,
        0.0021388899159444715,
        0.0003606138183354066,
    ],
    &[
        0.060791710043591234,
        0.10291567751758214,
        0.1223556620460092,
        0.127569246937016,
        0.12301357460007091,
        0.11184724485548572,
        0.09659638515212435,
        0.07935666435147314,
        0.061850494581965204,
        0.04543524650772667,
        0.031098974751581805,
        0.01945976592736084,
        0.010776254963205526,
        0.0049725428900876415,
        0.0016782011100511945,
        0.0002823537646684363,
    ],
    &[
        0.0554350690606789,
        0.09471876918947605,
        0.11388014116242869,
        0.12035501399822902,
        0.117980764446305,
        0.10943125792984233,
        0.096831291683709,
        0.08195310820994943,
        0.06627959712303574,
        0.05101928436045638,
        0.03710537132031794,
        0.025193114392029037,
        0.015662456142051126,
        0.008629247479119454,
        0.003966387616608936,
        0.0013349182473000303,
        0.00022420763846293725,
    ],
    &[
        0.05078475691502318,
        0.08749182176987103,
        0.10623198707242709,
        0.11360096280311896,
        0.11294042101485768,
        0.10654092905456052,
        0.09620780325696901,
        0.0834492524143092,
        0.06954227949220135,
        0.05555250775269276,
        0.042336679719951226,
        0.030540545134394265,
        0.020598370412719447,
        0.012737251354385463,
        0.006987759379525826,
        0.003201435711409616,
        0.001074955265635575,
        0.0001802814759478007,
    ],
    &[
        0.04671935251569589,
        0.08108711173508966,
        0.09931768881513423,
        0.10730668628785285,
        0.10799322403667383,
        0.10336070322219391,
        0.09495784781531387,
        0.0840770856575388,
        0.07182092876787241,
        0.05912498410595629,
        0.04676340179637811,
        0.03534814011738767,
        0.0253276486089719,
        0.01698790522390899,
        0.010457344969456252,
        0.005716389413311425,
        0.0026117408723496365,
        0.0008752154441082508,
        0.00014660059480602365,
    ],
    &[
        0.043142752133208076,
        0.07538370990858936,
        0.09305326745166305,
        0.10145671184982975,
        0.10320176205607207,
        0.10002254980527317,
        0.09325979930029768,
        0.08402895287194105,
        0.07328558913003073,
        0.06185033691373029,
        0.05041660443837468,
        0.03955137000529838,
        0.029694077895812843,
        0.0211563153554271,
        0.014123732938964021,
        0.008660974504335499,
        0.004719940146203605,
        0.002151397403965206,
        0.0007197282146532026,
        0.00012042767633021674,
    ],
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Gauss–Legendre is exact for xᵏ, k < 2n; expected value is the analytic ∫₋₁¹ xᵏ dx = 2/(k+1) (k even), 0
    /// (k odd). Tolerance 1e-14 relative, widened to (k+1)·2e-16 for high powers (a node error of one ulp is
    /// amplified k times in xᵏ).
    #[test]
    fn gauss_legendre_exact_for_monomials() {
        let mut worst: f64 = 0.0;
        for n in 1..=40 {
            let r = gauss_legendre(n).unwrap();
            assert_eq!(r.len(), n);
            for k in 0..2 * n {
                let exact = if k % 2 == 0 { 2.0 / (k as f64 + 1.0) } else { 0.0 };
                let s: f64 = r.iter().map(|(x, w)| w * x.powi(k as i32)).sum();
                let err = (s - exact).abs() / exact.abs().max(2.0 / (2 * n) as f64);
                worst = worst.max(err / (k as f64 + 1.0));
                let tol = 1e-14_f64.max((k as f64 + 1.0) * 2e-16);
                assert!(err < tol, "n={n} k={k}: {s} vs {exact}");
            }
            // symmetric, increasing, inside (-1, 1)
            for i in 0..n {
                assert_eq!(r.points[i], -r.points[n - 1 - i]);
                assert!(r.points[i].abs() < 1.0);
                if i > 0 {
                    assert!(r.points[i] > r.points[i - 1]);
                }
            }
        }
        eprintln!("gauss_legendre worst relative moment error / (k+1) (n<=40): {worst:e}");
    }

    /// Larger n still integrates a smooth function: ∫₋₁¹ eˣ dx = e − 1/e (analytic).
    #[test]
    fn gauss_legendre_large_n() {
        for n in [50, 64, 100] {
            let s: f64 = gauss_legendre(n).unwrap().iter().map(|(x, w)| w * x.exp()).sum();
            let exact = std::f64::consts::E - 1.0 / std::f64::consts::E;
            assert!((s - exact).abs() < 1e-14 * exact, "n={n}");
        }
    }

    /// The logarithmic rule reproduces the analytic moments ∫₀¹ −ln(t) tᵏ dt = 1/(k+1)² for k < 2n.
    #[test]
    fn log_gauss_reproduces_moments() {
        let mut worst: f64 = 0.0;
        for n in 1..=LOG_GAUSS_MAX {
            let r = log_gauss(n);
            assert_eq!(r.len(), n);
            for k in 0..2 * n {
                let exact = 1.0 / ((k + 1) * (k + 1)) as f64;
                let s: f64 = r.iter().map(|(t, w)| w * t.powi(k as i32)).sum();
                let err = (s - exact).abs() / exact;
                worst = worst.max(err);
                assert!(err < 1e-14, "n={n} k={k}: {s} vs {exact} (rel {err:e})");
            }
            assert!(r.iter().all(|(t, w)| t > 0.0 && t < 1.0 && w > 0.0));
        }
        eprintln!("log_gauss worst relative moment error (n<=20, k<2n): {worst:e}");
    }

    /// The cached accessors return the same rules as the constructors.
    #[test]
    fn caches_match() {
        assert_eq!(*gl(7), gauss_legendre(7).unwrap());
        assert_eq!(gauss_legendre(0).unwrap_err().argument, "n", "refused, not a panic");
        assert_eq!(*lg(9), log_gauss(9));
        assert!(std::ptr::eq(gl(7), gl(7)));
    }
}
