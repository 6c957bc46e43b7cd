// The marker lupdate reads in core: core has no Qt, so it only returns its text. The GUI
// translates the text later under the context given here (MessageText, ParamInfo, notes).
#pragma once

#ifndef QT_TRANSLATE_NOOP
#define QT_TRANSLATE_NOOP(context, text) text
#endif
