"""Chapter 12 · Bayes and particle filters: why a particle cloud collapses and what helps (Trace), and
the order of one particle filter step (Design)."""

from __future__ import annotations

from ..kinds.design import Design, Step
from ..kinds.trace import Option, Trace

EXERCISES = (
    Trace(
        id="12.6",
        title="Why the particles collapse",
        answer="c",
        options=(
            Option("a", "The weights were not normalised, so the resampler drew from the wrong distribution",
                   "Normalising changes no ratio between weights, and the filter in the story normalises them "
                   "before it resamples. The collapse happens with weights that add up to exactly 1."),
            Option("b", "Systematic resampling is biased: with a multinomial resampler the cloud would keep "
                        "its spread",
                   "Both resamplers copy the heavy particles and drop the light ones; systematic resampling only "
                   "does it with less randomness. With no noise to tell the copies apart, a multinomial "
                   "resampler collapses too, only by a more random path."),
            Option("c", "Each resampling copies some particles and drops others, and with no motion noise the "
                        "copies stay identical: add a little noise to each copy (roughening), or use more particles",
                   "Right. Resampling keeps N particles but fewer different ones: every step some are copied and "
                   "others lost. A motion update with noise would spread the copies apart again, but a robot "
                   "standing still adds none, so after a few rounds the cloud is a handful of points, or one, "
                   "and if the truth is not among them the filter cannot recover. Roughening (a small random "
                   "jitter of each resampled particle) keeps the cloud spread; more particles make losing the "
                   "good ones slower; resampling only when N_eff falls below about N/2 wastes fewer."),
            Option("d", "The range sensor's σ is too large, so the weights carry no information",
                   "A large σ makes the weights nearly equal, and then N_eff stays near N and the resampler "
                   "copies almost every particle once: that slows the collapse down. It is a σ too small "
                   "(an overconfident sensor model) that hands nearly all the weight to one particle."),
        ),
    ),
    Design(
        id="12.7",
        title="One step of a particle filter",
        steps=(
            Step("move", "Move every particle by the odometry $u$, adding the motion noise"),
            Step("weigh", "Weight each particle by the likelihood $p(z \\mid x_i)$ of the measurement"),
            Step("norm", "Normalise the weights so that they add up to 1"),
            Step("neff", "Compute $N_\\text{eff} = 1 / \\sum w_i^2$"),
            Step("resample", "If $N_\\text{eff} < N/2$, resample systematically and set every weight to $1/N$"),
        ),
        shown=("norm", "resample", "move", "neff", "weigh"),
    ),
)
