//! Sampling: a sinusoid's samples, their spectrum, the reconstruction and the alias (lesson 22).

use std::f32::consts::TAU;

use pipeline::mesh::signal::{Signal, Wheel};

fn signal(frequency: f32, rate: f32, blur: f32) -> Signal {
    Signal {
        frequency,
        rate,
        blur,
    }
}

/// Below f_s/2 the reconstruction from the samples is the signal; above, it is the alias
/// f_s − f (with the sign of the folded sine): f = 14, f_s = 20 reconstructs −sin(2π·6·t).
#[test]
fn reconstruction_gives_the_signal_or_its_alias() {
    let slow = signal(3.0, 20.0, 0.0);
    let fast = signal(14.0, 20.0, 0.0);
    assert_eq!(slow.alias(), 3.0);
    assert_eq!(fast.alias(), 6.0);
    for k in 0..=60 {
        let t = 0.2 + 0.6 * k as f32 / 60.0;
        assert!(
            (slow.reconstruction(t) - slow.value(t)).abs() < 0.03,
            "t = {t}"
        );
        assert!(
            (fast.reconstruction(t) + (TAU * 6.0 * t).sin()).abs() < 0.03,
            "t = {t}"
        );
    }
}

/// The box filter's gain is sinc(f·W): 0.37 at f = 14 for a box of one sample at f_s = 20 and 0.86
/// at 6, lesson 22's worked answer.
#[test]
fn the_box_filter_attenuates_by_sinc() {
    assert!((signal(14.0, 20.0, 1.0).blur_gain() - 0.3679).abs() < 1e-3);
    assert!((signal(6.0, 20.0, 1.0).blur_gain() - 0.8584).abs() < 1e-3);
    assert_eq!(signal(6.0, 20.0, 0.0).blur_gain(), 1.0);
}

/// The samples' spectrum has unit peaks at ±f + k·f_s and nothing much elsewhere.
#[test]
fn the_spectrum_of_the_samples_repeats_at_multiples_of_the_rate() {
    let s = signal(3.0, 20.0, 0.0);
    let spectrum = s.spectrum();
    let at = |nu: f32| {
        spectrum
            .iter()
            .filter(|p| (p.x - nu).abs() < 0.2)
            .map(|p| p.y)
            .fold(0.0f32, f32::max)
    };
    for nu in [-37.0, -23.0, -17.0, -3.0, 3.0, 17.0, 23.0, 37.0] {
        assert!((at(nu) - 1.0).abs() < 0.05, "peak at {nu}: {}", at(nu));
    }
    for nu in [-30.0, -10.0, 0.0, 8.0, 12.0, 28.0] {
        assert!(at(nu) < 0.05, "nothing at {nu}: {}", at(nu));
    }
}

/// The wheel seems to turn by the true step folded to the nearest spoke.
#[test]
fn a_wheel_filmed_too_slowly_turns_backwards() {
    let wheel = |step: f32| Wheel {
        spokes: 8,
        step,
        frames: 5,
    };
    assert_eq!(wheel(10.0).apparent_step(), 10.0);
    assert!((wheel(40.0).apparent_step() + 5.0).abs() < 1e-5);
    assert!(wheel(45.0).apparent_step().abs() < 1e-5);
    assert!((wheel(50.0).apparent_step() - 5.0).abs() < 1e-5);
}
