//! The built-in meshes of sampling: `signal`, a 1-D signal with its samples and its reconstruction
//! above its spectrum (computed with `rustfft`), and `wheel`, a spoked wheel filmed frame by frame.
//! Both are drawings in the plane z = 0, like a Bézier construction.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};
use rustfft::FftPlanner;
use rustfft::num_complex::Complex;
use serde::Serialize;

use super::drawing::{polyline, quad, square};
use super::{Mesh, MeshLabel};

const AXIS: Vec3 = Vec3::new(0.45, 0.47, 0.52);
const SIGNAL: Vec3 = Vec3::new(0.75, 0.77, 0.82);
const SAMPLE: Vec3 = Vec3::new(1.0, 0.85, 0.2);
const RECONSTRUCTED: Vec3 = Vec3::new(0.95, 0.35, 0.3);
const BAND: Vec3 = Vec3::new(0.16, 0.2, 0.28);

/// The plot's half-width in x; the time axis shows t ∈ [0, 1], the frequency axis ν ∈ [−40, 40].
const HALF_W: f32 = 1.45;
/// The frequency axis's half-range, cycles per unit time.
const NU_MAX: f32 = 40.0;

/// A sinusoid `sin(2π·f·t)`, optionally blurred by a box filter, sampled at `rate` samples per
/// unit time and reconstructed from its samples; below, the spectrum of the samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Signal {
    /// The signal's frequency `f`, cycles per unit time.
    pub frequency: f32,
    /// The sampling rate `f_s`, samples per unit time.
    pub rate: f32,
    /// The width of the box filter applied **before** sampling, in sample spacings (0: none).
    pub blur: f32,
}

impl Signal {
    /// The box filter's effect on `sin(2πft)`: its amplitude times
    /// `sinc(f·W) = sin(π·f·W)/(π·f·W)` for a box of width `W = blur/f_s` (the Fourier transform of
    /// the box).
    #[must_use]
    pub fn blur_gain(&self) -> f32 {
        let x = PI * self.frequency * self.blur / self.rate;
        if x.abs() < 1e-6 { 1.0 } else { x.sin() / x }
    }

    /// The signal after the box filter, at time `t`.
    #[must_use]
    pub fn value(&self, t: f32) -> f32 {
        self.blur_gain() * (TAU * self.frequency * t).sin()
    }

    /// The frequency the samples show: `f` folded into `[0, f_s/2]`, `|f − f_s·round(f/f_s)|`.
    #[must_use]
    pub fn alias(&self) -> f32 {
        (self.frequency - self.rate * (self.frequency / self.rate).round()).abs()
    }

    /// The ideal (Whittaker–Shannon) reconstruction `Σ_k x(k/f_s)·sinc(f_s·t − k)` at `t`, over
    /// the samples of t ∈ [−4, 5] (enough that the window's ends do not show on [0, 1]).
    #[must_use]
    pub fn reconstruction(&self, t: f32) -> f32 {
        let (lo, hi) = ((-4.0 * self.rate) as i32, (5.0 * self.rate) as i32);
        (lo..=hi)
            .map(|k| {
                let x = self.rate * t - k as f32;
                let sinc = if x.abs() < 1e-6 {
                    1.0
                } else {
                    (PI * x).sin() / (PI * x)
                };
                self.value(k as f32 / self.rate) * sinc
            })
            .sum()
    }

    /// The magnitude spectrum of the sampled signal on ν ∈ [−40, 40]: the samples over 16 units
    /// of time, Hann-windowed, as impulses on a grid `K` times finer than the samples (so every
    /// sample falls exactly on a grid point, and the grid's own Nyquist frequency is above 40),
    /// through an FFT (`rustfft`), normalised so that a unit sinusoid's peak is 1. Sampling makes
    /// copies of the signal's spectrum at every multiple of f_s, which this shows without being
    /// told.
    #[must_use]
    pub fn spectrum(&self) -> Vec<Vec2> {
        const UNITS: f32 = 16.0;
        let k_fine = (2.0 * NU_MAX / self.rate).ceil() as usize + 1;
        let n = ((UNITS * self.rate).floor() as usize * k_fine).max(1);
        let samples = n / k_fine;
        let mut buffer = vec![Complex::new(0.0f32, 0.0); n];
        let mut weight = 0.0;
        for k in 0..samples {
            let hann = 0.5 - 0.5 * (TAU * k as f32 / samples as f32).cos();
            buffer[k * k_fine].re = self.value(k as f32 / self.rate) * hann;
            weight += hann;
        }
        FftPlanner::new().plan_fft_forward(n).process(&mut buffer);
        // Bin b is the frequency b/(n·dt) with dt = 1/(f_s·K).
        let per_bin = self.rate * k_fine as f32 / n as f32;
        let last = (NU_MAX / per_bin).floor() as i64;
        (-last..=last)
            .map(|b| {
                let c = buffer[b.rem_euclid(n as i64) as usize];
                Vec2::new(b as f32 * per_bin, 2.0 * c.norm() / weight.max(1e-6))
            })
            .collect()
    }

    /// The drawing: above, the signal (grey), its samples (yellow) and the reconstruction from
    /// them (red) over t ∈ [0, 1]; below, the samples' spectrum with the band [−f_s/2, f_s/2]
    /// that reconstruction keeps shaded, and labels for f, f_s and the alias f_a (in notation, so
    /// that they read the same in either language).
    #[must_use]
    pub fn build(&self) -> Mesh {
        let mut m = Mesh {
            name: "signal".into(),
            ..Mesh::default()
        };
        let time = |t: f32, y: f32| Vec2::new(-HALF_W + 2.0 * HALF_W * t, 0.5 + 0.3 * y);
        let freq = |nu: f32, a: f32| Vec2::new(nu / NU_MAX * HALF_W, -0.85 + 0.55 * a.min(1.3));
        // Axes.
        polyline(&mut m, &[time(0.0, 0.0), time(1.0, 0.0)], 0.006, 0.0, AXIS);
        polyline(
            &mut m,
            &[freq(-NU_MAX, 0.0), freq(NU_MAX, 0.0)],
            0.006,
            0.0,
            AXIS,
        );
        // The kept band.
        let half = (self.rate / 2.0).min(NU_MAX);
        let (a, b) = (freq(-half, 0.0), freq(half, 1.25));
        quad(
            &mut m,
            [a, Vec2::new(b.x, a.y), b, Vec2::new(a.x, b.y)],
            -0.001,
            BAND,
        );
        let curve = |f: &dyn Fn(f32) -> f32| -> Vec<Vec2> {
            (0..=400)
                .map(|k| k as f32 / 400.0)
                .map(|t| time(t, f(t)))
                .collect()
        };
        polyline(&mut m, &curve(&|t| self.value(t)), 0.008, 0.001, SIGNAL);
        polyline(
            &mut m,
            &curve(&|t| self.reconstruction(t)),
            0.012,
            0.002,
            RECONSTRUCTED,
        );
        let count = (self.rate.floor() as usize).min(400);
        for k in 0..=count {
            let t = k as f32 / self.rate;
            if t <= 1.0 {
                square(&mut m, time(t, self.value(t)), 0.03, 0.003, SAMPLE);
            }
        }
        let spectrum: Vec<Vec2> = self.spectrum().iter().map(|p| freq(p.x, p.y)).collect();
        polyline(&mut m, &spectrum, 0.008, 0.002, SAMPLE);
        m.normals = vec![Vec3::Z; m.positions.len()];
        let label = |m: &mut Mesh, p: Vec2, text: String| {
            m.labels.push(MeshLabel {
                position: p.extend(0.01),
                text,
            });
        };
        label(
            &mut m,
            time(0.2, 1.5),
            format!("f = {:.1}, f_s = {:.1}", self.frequency, self.rate),
        );
        label(&mut m, freq(half, 1.38), "f_s/2".into());
        label(&mut m, freq(-half, 1.38), "−f_s/2".into());
        label(
            &mut m,
            time(0.85, 1.5),
            format!("f_a = {:.1}", self.alias()),
        );
        label(&mut m, freq(NU_MAX, -0.22), "ν".into());
        label(&mut m, time(1.0, -0.22), "t".into());
        m
    }
}

/// A wheel with `spokes` spokes (one red) that turns by `step` degrees between two frames of a
/// film, drawn as `frames` frames side by side: sampling in time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Wheel {
    /// Spokes, evenly spaced.
    pub spokes: u32,
    /// The true rotation between frames, degrees (counter-clockwise).
    pub step: f32,
    /// How many frames are drawn (1…8).
    pub frames: u32,
}

impl Wheel {
    /// The rotation the eye sees between frames: the true step folded to the nearest spoke,
    /// `step − (360°/spokes)·round(step·spokes/360°)` (negative: it seems to turn backwards).
    #[must_use]
    pub fn apparent_step(&self) -> f32 {
        let period = 360.0 / self.spokes.max(1) as f32;
        self.step - period * (self.step / period).round()
    }

    /// The frames, left to right, each labelled with its number.
    #[must_use]
    pub fn build(&self) -> Mesh {
        let mut m = Mesh {
            name: "wheel".into(),
            ..Mesh::default()
        };
        let frames = self.frames.clamp(1, 8);
        let spacing = 2.9 / frames as f32;
        let r = (spacing * 0.42).min(0.6);
        for f in 0..frames {
            let centre = Vec2::new(-1.45 + spacing * (f as f32 + 0.5), 0.0);
            let rim: Vec<Vec2> = (0..=64)
                .map(|k| centre + Vec2::from_angle(TAU * k as f32 / 64.0) * r)
                .collect();
            polyline(&mut m, &rim, 0.02, 0.0, SIGNAL);
            let turn = (self.step * f as f32).to_radians();
            for s in 0..self.spokes.max(1) {
                let angle = turn + TAU * s as f32 / self.spokes.max(1) as f32;
                let color = if s == 0 { RECONSTRUCTED } else { SIGNAL };
                let tip = centre + Vec2::from_angle(angle) * r;
                polyline(
                    &mut m,
                    &[centre, tip],
                    0.02,
                    0.001 * (s == 0) as u8 as f32,
                    color,
                );
            }
            m.labels.push(MeshLabel {
                position: (centre - Vec2::Y * (r + 0.14)).extend(0.0),
                text: format!("{}", f + 1),
            });
        }
        m.normals = vec![Vec3::Z; m.positions.len()];
        m.labels.push(MeshLabel {
            position: Vec3::new(0.0, 0.85, 0.0),
            text: format!(
                "Δθ = {:.1}°, Δθ_a = {:.1}°",
                self.step,
                self.apparent_step()
            ),
        });
        m
    }
}
