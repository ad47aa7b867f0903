//! The elastic constants of a body: `material = "steel"`, or `e` and `nu`; both is refused.

use std::ops::Range;

use toml::Spanned;

use super::Reader;
use crate::error::{ErrorKind, SceneError};
use crate::materials;
use crate::raw::SQty;
use crate::scene::Elastic;
use crate::units::Dim;

/// The keys of one body's elastic constants as written.
pub(super) struct Keys<'a> {
    /// "substrate" or "indenter".
    pub table: &'static str,
    /// Its span, for a missing key.
    pub span: Range<usize>,
    pub material: Option<&'a Spanned<String>>,
    pub e: Option<&'a SQty>,
    pub nu: Option<&'a Spanned<f64>>,
    /// What `e` is, for the hint when it is missing ("Young's modulus, e.g. ...").
    pub e_what: &'static str,
}

/// E and nu of the body: from the named material, or from `e` and `nu`.
pub(super) fn elastic(cx: &Reader<'_>, k: &Keys<'_>) -> Result<Elastic, SceneError> {
    let t = k.table;
    let Some(m) = k.material else {
        let e = cx.required(&k.e, &format!("{t}.e"), k.span.clone(), k.e_what)?;
        // Worded as the format's other missing keys are (schema.rs): the key as written.
        let nu = k.nu.ok_or_else(|| {
            cx.err(
                ErrorKind::Schema,
                &format!("{t}.nu"),
                Some(k.span.clone()),
                format!("missing key `nu` in [{t}]"),
            )
            .hint("add nu = a number (or material = \"steel\" for both e and nu)")
        })?;
        return Ok(Elastic {
            e: cx.qty(e, &format!("{t}.e"), Dim::STRESS, "modulus")?,
            nu: cx.num(nu, &format!("{t}.nu")),
        });
    };
    let mkey = format!("{t}.material");
    cx.record(&mkey, m.span());
    let Some(found) = materials::lookup(m.get_ref()) else {
        return Err(cx
            .err(
                ErrorKind::Schema,
                &mkey,
                Some(m.span()),
                format!("unknown material \"{}\"", m.get_ref()),
            )
            .hint(format!(
                "one of: {} (docs/materials.md); or give e and nu instead of material",
                materials::names()
            )));
    };
    let both = |key: &str, span: Range<usize>| {
        cx.err(
            ErrorKind::Schema,
            &format!("{t}.{key}"),
            Some(span),
            format!("`{key}` given together with material = \"{}\", which sets e and nu", m.get_ref()),
        )
        .hint(format!(
            "remove `e` and `nu` to use {} (E = {}, nu = {}), or remove `material` to give your own",
            found.name,
            materials::modulus(found.e),
            found.nu
        ))
    };
    if let Some(e) = k.e {
        return Err(both("e", e.span()));
    }
    if let Some(nu) = k.nu {
        return Err(both("nu", nu.span()));
    }
    // A later refusal of e or nu points at the material that gave them.
    cx.record(&format!("{t}.e"), m.span());
    cx.record(&format!("{t}.nu"), m.span());
    cx.materials.borrow_mut().push((t.to_string(), *found));
    Ok(found.elastic())
}

/// A named material where the model takes none (a graded substrate, a rigid indenter).
pub(super) fn refuse(
    cx: &Reader<'_>,
    table: &str,
    material: Option<&Spanned<String>>,
    why: &str,
    hint: &str,
) -> Result<(), SceneError> {
    match material {
        None => Ok(()),
        Some(m) => Err(cx
            .err(ErrorKind::Schema, &format!("{table}.material"), Some(m.span()), why.to_string())
            .hint(hint.to_string())),
    }
}
