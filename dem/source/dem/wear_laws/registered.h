// The registered wear laws, one line each: ABRADE_WEAR_LAW(Class), where Class is defined in
// its own file of this folder and made by ABRADE_WEAR_LAW_FACTORY(Class) there (plugin.h). The
// order is the order of `abrade params`, of the output columns and of the allowed names.
ABRADE_WEAR_LAW(Archard)
ABRADE_WEAR_LAW(Relative)
ABRADE_WEAR_LAW(Finnie)
ABRADE_WEAR_LAW(Oka)
