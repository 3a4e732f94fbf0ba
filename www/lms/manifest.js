// The imsmanifest.xml of a practice package: one organization, one item, one
// SCO resource (the practice page) listing every file of the package — for
// SCORM 1.2 (IMS CP 1.1.2 + ADL CP 1.2) or SCORM 2004 4th Edition (IMS CP 1.1
// + ADL CP/SEQ/NAV 1.3 + IMS SS). The namespaces and schema locations are the
// ones the ADL's conformance packages use; the XSD files themselves are not
// shipped (no LMS needs them, and they are not on a package registry).

const NS = {
  "1.2": {
    manifest: 'version="1.0" xmlns="http://www.imsproject.org/xsd/imscp_rootv1p1p2" xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_rootv1p2" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.imsproject.org/xsd/imscp_rootv1p1p2 imscp_rootv1p1p2.xsd http://www.imsglobal.org/xsd/imsmd_rootv1p2p1 imsmd_rootv1p2p1.xsd http://www.adlnet.org/xsd/adlcp_rootv1p2 adlcp_rootv1p2.xsd"',
    schemaversion: "1.2",
    scormType: "adlcp:scormtype",
  },
  2004: {
    manifest:
      'version="1" xmlns="http://www.imsglobal.org/xsd/imscp_v1p1" xmlns:adlcp="http://www.adlnet.org/xsd/adlcp_v1p3" xmlns:adlseq="http://www.adlnet.org/xsd/adlseq_v1p3" xmlns:adlnav="http://www.adlnet.org/xsd/adlnav_v1p3" xmlns:imsss="http://www.imsglobal.org/xsd/imsss" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://www.imsglobal.org/xsd/imscp_v1p1 imscp_v1p1.xsd http://www.adlnet.org/xsd/adlcp_v1p3 adlcp_v1p3.xsd http://www.adlnet.org/xsd/adlseq_v1p3 adlseq_v1p3.xsd http://www.adlnet.org/xsd/adlnav_v1p3 adlnav_v1p3.xsd http://www.imsglobal.org/xsd/imsss imsss_v1p0.xsd"',
    schemaversion: "2004 4th Edition",
    scormType: "adlcp:scormType",
  },
};

/** Text for XML content or an attribute value. */
export function xmlText(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&apos;" })[c]);
}

/** An xs:ID: a letter or _, then letters, digits, _ - . (the manifest's identifiers). */
export function xmlId(s) {
  const t = String(s).replace(/[^A-Za-z0-9_.-]/g, "_");
  return /^[A-Za-z_]/.test(t) ? t : `_${t}`;
}

/**
 * The manifest text. `version`: "1.2" or "2004"; `identifier`: the package's
 * id (unique per package); `title`; `launch`: the SCO's page (relative path);
 * `files`: every file of the package but the manifest (relative paths, "/"
 * separated); `passing`: the passing percentage or null (1.2:
 * adlcp:masteryscore; 2004: the primary objective satisfied by measure).
 */
export function manifestXml({ version = "1.2", identifier, title, launch, files, passing = null }) {
  const ns = NS[version];
  if (!ns) throw new Error(`version: "${version}" is not a SCORM version this playground writes ("1.2" or "2004")`);
  if (!files.includes(launch)) throw new Error(`launch: "${launch}" is not among the package's files`);
  const id = xmlId(identifier);
  const t = xmlText(title);
  const fileLines = files.map((f) => `      <file href="${xmlText(f)}"/>`).join("\n");
  let itemExtra = "";
  if (version === "1.2" && passing != null) itemExtra = `\n        <adlcp:masteryscore>${Math.round(passing)}</adlcp:masteryscore>`;
  if (version === "2004") {
    const objective =
      passing != null
        ? `<imsss:primaryObjective objectiveID="passing" satisfiedByMeasure="true"><imsss:minNormalizedMeasure>${Math.round(passing) / 100}</imsss:minNormalizedMeasure></imsss:primaryObjective>`
        : `<imsss:primaryObjective objectiveID="practice"/>`;
    itemExtra = `\n        <imsss:sequencing><imsss:objectives>${objective}</imsss:objectives><imsss:deliveryControls tracked="true" completionSetByContent="true" objectiveSetByContent="true"/></imsss:sequencing>`;
  }
  return `<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="${id}" ${ns.manifest}>
  <metadata>
    <schema>ADL SCORM</schema>
    <schemaversion>${ns.schemaversion}</schemaversion>
  </metadata>
  <organizations default="org">
    <organization identifier="org">
      <title>${t}</title>
      <item identifier="item" identifierref="sco" isvisible="true">
        <title>${t}</title>${itemExtra}
      </item>
    </organization>
  </organizations>
  <resources>
    <resource identifier="sco" type="webcontent" ${ns.scormType}="sco" href="${xmlText(launch)}">
${fileLines}
    </resource>
  </resources>
</manifest>
`;
}
