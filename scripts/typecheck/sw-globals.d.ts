// The names docs/hooks/offline.py fills into the service worker's template (declarations only).
/** A hash of every file of the build. */
declare const __WB_VERSION__: string;
/** The manifest: [URL relative to the site root, "sha256-…", size, and for the snapshot its stored sha256 and size]. */
declare const __WB_FILES__: Array<[string, string, number, string?, number?]>;
/** The whole copy's download, gzip as the host sends it. */
declare const __WB_WIRE_BYTES__: number;
/** Files kept when first fetched, not with the copy: entries as in the manifest. */
declare const __WB_LATER__: Array<[string, string, number, string?, number?]>;
