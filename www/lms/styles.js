// The LMS kit's stylesheet, added once by whichever of its views opens first.

import { addStylesheet } from "../dom.js";

const STYLESHEET = new URL("./lms.css", import.meta.url).href; // (the build gives it its hashed name)

export function lmsStyles() {
  addStylesheet(STYLESHEET);
}
