#!/usr/bin/env bash
# Writes a Unity .meta file next to every file and folder Unity imports from this package
# (everything except hidden entries, folders ending in "~", and build outputs), with a GUID
# derived from the path so that it is stable across machines. Existing .meta files are kept.
# Usage: bash Tools~/generate-meta.sh   (from anywhere; run after adding files)
set -euo pipefail
cd "$(dirname "$0")/.."

guid_of() { printf '%s' "com.fulcrum.physics/$1" | md5sum | cut -c1-32; }

importer_for() {
  case "$1" in
    *.cs) printf 'MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n' ;;
    *.asmdef) printf 'AssemblyDefinitionImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n' ;;
    *.json|*.md|*.txt|*.csv) printf 'TextScriptImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n' ;;
    *) printf 'DefaultImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n' ;;
  esac
}

count=0
while IFS= read -r -d '' path; do
  rel=${path#./}
  meta="$rel.meta"
  [ -e "$meta" ] && continue
  {
    printf 'fileFormatVersion: 2\nguid: %s\n' "$(guid_of "$rel")"
    if [ -d "$rel" ]; then
      printf 'folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n'
    else
      importer_for "$rel"
    fi
  } > "$meta"
  count=$((count + 1))
done < <(find . -mindepth 1 \( -name '.*' -o -name '*~' -o -name bin -o -name obj \) -prune -o ! -name '*.meta' -print0)
echo "wrote $count .meta files"
