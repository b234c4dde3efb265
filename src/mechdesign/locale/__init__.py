"""The translation catalogues (gettext .po, one per language; see mechdesign.i18n)."""
