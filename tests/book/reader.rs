//! Tests of `sliding_ladder::book::reader` (src/book/reader.rs).

use sliding_ladder::book::reader::{badge, status_word};
use sliding_ladder::verify::Status;

#[test]
fn readers_words_differ_from_the_technical_ones_where_they_must() {
    assert_eq!(status_word(Status::Verified), "checked");
    assert_eq!(status_word(Status::Erratum), "misprint in the note");
    assert!(badge(Status::Erratum).contains("class=\"badge erratum\""));
    assert!(badge(Status::Verified).contains("glossary.html#checked"));
}
