//! `ladder simulate`: bad scenes, random scenes, every method, the summary.

mod random_scenes;
mod scene_errors;
mod summary_digits;
mod taylor_every_scene;
