//! docs/case-format.md documents every key of the case format: each key of
//! the JSON Schema must appear there as `section.key`.

use rolldyn_case::json_schema;
use serde_json::Value;

fn resolve<'a>(schema: &'a Value, defs: &'a Value) -> &'a Value {
    if let Some(r) = schema.get("$ref").and_then(Value::as_str) {
        return &defs[r.rsplit('/').next().unwrap_or_default()];
    }
    if let Some(any) = schema.get("anyOf").and_then(Value::as_array) {
        if let Some(non_null) = any
            .iter()
            .find(|s| s.get("type").and_then(Value::as_str) != Some("null"))
        {
            return resolve(non_null, defs);
        }
    }
    schema
}

fn keys(schema: &Value, defs: &Value, prefix: &str, out: &mut Vec<String>) {
    let Some(props) = resolve(schema, defs)
        .get("properties")
        .and_then(Value::as_object)
    else {
        return;
    };
    for (k, v) in props {
        let path = format!("{prefix}{k}");
        // Material and law tables are documented by their own keys' tables.
        if ![
            "materials.ball",
            "materials.rings",
            "cage.material",
            "model.normal_law",
        ]
        .contains(&path.as_str())
            // Random-waviness laws: one table of their keys in the docs.
            && !path.ends_with("random_radial_waviness")
            && !path.ends_with("random_axial_waviness")
            && !path.ends_with("random_waviness")
        {
            keys(v, defs, &format!("{path}."), out);
        }
        out.push(path);
    }
}

#[test]
fn every_schema_key_is_documented() {
    let schema = json_schema();
    let defs = schema.get("$defs").cloned().unwrap_or(Value::Null);
    let mut all = Vec::new();
    keys(&schema, &defs, "", &mut all);
    assert!(all.len() > 40, "schema walk found {} keys", all.len());
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/case-format.md"
    ))
    .expect("docs/case-format.md exists");
    let sections = [
        "bearing",
        "cage",
        "inner_ring",
        "outer_ring",
        "drag",
        "seals",
        "sensor",
        "materials",
        "lubricant",
        "lubrication",
        "operating",
        "model",
        "solver",
        "output",
        "surface",
        "power",
        "thermal",
        "life",
        "arrangement",
        "shaft",
        "fits",
    ];
    for key in all {
        let documented = if sections.contains(&key.as_str()) {
            doc.contains(&format!("[{key}]"))
        } else {
            doc.contains(&format!("`{key}`"))
        };
        assert!(documented, "docs/case-format.md does not document `{key}`");
    }
}
