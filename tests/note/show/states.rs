//! `ladder show`'s evaluation at random user states (library level, fast): every printed form of
//! every display is finite, and where the forms must agree they agree within the running error
//! bound; every recorded misprint differs in value or units. Random `--at` text never panics.

use proptest::prelude::*;
use sliding_ladder::registry::equations;
use sliding_ladder::show::{at::parse_at, expectation, state::build, values};

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn forms_agree_at_random_states(
        lm in -3.0..3.0f64, ll in -3.0..3.0f64, lg in -2.0..2.0f64,
        theta in 0.0..89.9f64, frac0 in 0.0..1.0f64,
    ) {
        let text = format!(
            "m={:e}, l={:e}, g={:e}, theta={theta}deg, theta0={}deg",
            10f64.powf(lm), 10f64.powf(ll), 10f64.powf(lg), theta * frac0
        );
        let at = parse_at(&text).unwrap();
        let point = build(&at);
        for e in equations() {
            let forms = values::form_values(&e, &point).unwrap();
            let must = expectation(&e, &point.summary, values::place_of(&e).as_ref()).is_none();
            for f in &forms {
                prop_assert!(f.error.is_none(), "({}) {text}: {:?}", e.number, f.error);
                prop_assert!(f.value.iter().all(|v| v.is_finite()));
                if f.role == "misprint" {
                    prop_assert!(f.agrees == Some(false) || f.unit.starts_with("inconsistent"));
                } else if must {
                    prop_assert!(f.agrees != Some(false), "({}) {text}: form {} residual {:?}", e.number, f.index, f.residual);
                }
            }
        }
    }

    #[test]
    fn any_at_text_is_read_or_refused_in_one_line(s in ".{0,40}", k in 0usize..8, v in "[-+0-9./e]{0,12}(deg|rad)?") {
        let keys = ["m", "l", "g", "theta", "theta0", "sin_theta", "theta_dot", "theta_ddot"];
        for text in [s.clone(), format!("{}={v}", keys[k])] {
            if let Err(e) = parse_at(&text) {
                prop_assert!(!e.contains('\n') && e.starts_with("--at"));
            } else {
                let p = build(&parse_at(&text).unwrap());
                prop_assert!(p.float.1.rate.is_finite() && p.float.1.accel.is_finite());
            }
        }
    }
}
