#!/bin/sh
# Put ugnis on the desktop: the application entry and icon, the file types it opens (.flame,
# .flam3, .fla, .ifs, .ugr, .esc) and the thumbnailer that lets file managers show flames as
# their pictures.
#
#   contrib/desktop/install.sh            for you ($XDG_DATA_HOME, ~/.local/share)
#   sudo contrib/desktop/install.sh --system   for everyone (/usr/local/share)
#
# ugnis itself must be on the PATH (e.g. `cargo install --path .`, or copy
# target/release/ugnis to /usr/local/bin). GNOME's file manager runs thumbnailers in a
# sandbox that sees /usr but not your home: for thumbnails there, put the binary in
# /usr/local/bin rather than ~/.cargo/bin.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
case "${1:-}" in
  --system) share=/usr/local/share ;;
  "") share=${XDG_DATA_HOME:-$HOME/.local/share} ;;
  *) echo "usage: $0 [--system]" >&2; exit 2 ;;
esac
command -v ugnis >/dev/null 2>&1 || echo "note: ugnis is not on the PATH yet; the entry and the thumbnailer call 'ugnis'" >&2
install -D -m 644 "$here/ugnis.desktop" "$share/applications/ugnis.desktop"
install -D -m 644 "$here/ugnis.svg" "$share/icons/hicolor/scalable/apps/ugnis.svg"
install -D -m 644 "$here/ugnis-mime.xml" "$share/mime/packages/ugnis-mime.xml"
install -D -m 644 "$here/ugnis.thumbnailer" "$share/thumbnailers/ugnis.thumbnailer"
# Refresh the caches where the tools exist (a minimal system may lack them).
command -v update-mime-database >/dev/null 2>&1 && update-mime-database "$share/mime"
command -v update-desktop-database >/dev/null 2>&1 && update-desktop-database "$share/applications"
command -v gtk-update-icon-cache >/dev/null 2>&1 && gtk-update-icon-cache -q -t "$share/icons/hicolor" || true
echo "installed into $share (old thumbnails: rm -r ~/.cache/thumbnails to see new ones)"
