//! Work-precision (placeholder until written).
use std::path::Path;
use std::process::ExitCode;
/// `ladder work-precision [SCENE] [--json] [--out DIR]`.
pub fn command(_scene: Option<&Path>, _json: bool, _out: Option<&Path>) -> ExitCode {
    ExitCode::SUCCESS
}
