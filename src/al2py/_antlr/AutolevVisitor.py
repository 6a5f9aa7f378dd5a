# Generated from Autolev.g4 by ANTLR 4.13.2
from antlr4 import *
if "." in __name__:
    from .AutolevParser import AutolevParser
else:
    from AutolevParser import AutolevParser

# This class defines a complete generic visitor for a parse tree produced by AutolevParser.

class AutolevVisitor(ParseTreeVisitor):

    # Visit a parse tree produced by AutolevParser#statement.
    def visitStatement(self, ctx:AutolevParser.StatementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#stmt.
    def visitStmt(self, ctx:AutolevParser.StmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#assignment.
    def visitAssignment(self, ctx:AutolevParser.AssignmentContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#elementTarget.
    def visitElementTarget(self, ctx:AutolevParser.ElementTargetContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#nameTarget.
    def visitNameTarget(self, ctx:AutolevParser.NameTargetContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#exprStmt.
    def visitExprStmt(self, ctx:AutolevParser.ExprStmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declaration.
    def visitDeclaration(self, ctx:AutolevParser.DeclarationContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declKeyword.
    def visitDeclKeyword(self, ctx:AutolevParser.DeclKeywordContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#firstDeclItem.
    def visitFirstDeclItem(self, ctx:AutolevParser.FirstDeclItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declHead.
    def visitDeclHead(self, ctx:AutolevParser.DeclHeadContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declItem.
    def visitDeclItem(self, ctx:AutolevParser.DeclItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#declTail.
    def visitDeclTail(self, ctx:AutolevParser.DeclTailContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#sign.
    def visitSign(self, ctx:AutolevParser.SignContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputStmt.
    def visitInputStmt(self, ctx:AutolevParser.InputStmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputItem.
    def visitInputItem(self, ctx:AutolevParser.InputItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputElement.
    def visitInputElement(self, ctx:AutolevParser.InputElementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputIndexed.
    def visitInputIndexed(self, ctx:AutolevParser.InputIndexedContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#inputName.
    def visitInputName(self, ctx:AutolevParser.InputNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#outputStmt.
    def visitOutputStmt(self, ctx:AutolevParser.OutputStmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#outputItem.
    def visitOutputItem(self, ctx:AutolevParser.OutputItemContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitSystemStmt.
    def visitUnitSystemStmt(self, ctx:AutolevParser.UnitSystemStmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unit.
    def visitUnit(self, ctx:AutolevParser.UnitContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitOp.
    def visitUnitOp(self, ctx:AutolevParser.UnitOpContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unitFactor.
    def visitUnitFactor(self, ctx:AutolevParser.UnitFactorContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#codeStmt.
    def visitCodeStmt(self, ctx:AutolevParser.CodeStmtContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#sweep.
    def visitSweep(self, ctx:AutolevParser.SweepContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#fileCommand.
    def visitFileCommand(self, ctx:AutolevParser.FileCommandContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#fileName.
    def visitFileName(self, ctx:AutolevParser.FileNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#filePiece.
    def visitFilePiece(self, ctx:AutolevParser.FilePieceContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#setting.
    def visitSetting(self, ctx:AutolevParser.SettingContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingName.
    def visitSettingName(self, ctx:AutolevParser.SettingNameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingGroup.
    def visitSettingGroup(self, ctx:AutolevParser.SettingGroupContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingNumber.
    def visitSettingNumber(self, ctx:AutolevParser.SettingNumberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#settingWord.
    def visitSettingWord(self, ctx:AutolevParser.SettingWordContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#expr.
    def visitExpr(self, ctx:AutolevParser.ExprContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#additive.
    def visitAdditive(self, ctx:AutolevParser.AdditiveContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#addOp.
    def visitAddOp(self, ctx:AutolevParser.AddOpContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#multiplicative.
    def visitMultiplicative(self, ctx:AutolevParser.MultiplicativeContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#mulOp.
    def visitMulOp(self, ctx:AutolevParser.MulOpContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#signed.
    def visitSigned(self, ctx:AutolevParser.SignedContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#unsigned.
    def visitUnsigned(self, ctx:AutolevParser.UnsignedContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#power.
    def visitPower(self, ctx:AutolevParser.PowerContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#number.
    def visitNumber(self, ctx:AutolevParser.NumberContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#string.
    def visitString(self, ctx:AutolevParser.StringContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#special.
    def visitSpecial(self, ctx:AutolevParser.SpecialContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#call.
    def visitCall(self, ctx:AutolevParser.CallContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#element.
    def visitElement(self, ctx:AutolevParser.ElementContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexedNames.
    def visitIndexedNames(self, ctx:AutolevParser.IndexedNamesContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#name.
    def visitName(self, ctx:AutolevParser.NameContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#matrix.
    def visitMatrix(self, ctx:AutolevParser.MatrixContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#parens.
    def visitParens(self, ctx:AutolevParser.ParensContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#matrixRow.
    def visitMatrixRow(self, ctx:AutolevParser.MatrixRowContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#exprList.
    def visitExprList(self, ctx:AutolevParser.ExprListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#argList.
    def visitArgList(self, ctx:AutolevParser.ArgListContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#arg.
    def visitArg(self, ctx:AutolevParser.ArgContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexBraces.
    def visitIndexBraces(self, ctx:AutolevParser.IndexBracesContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#indexRange.
    def visitIndexRange(self, ctx:AutolevParser.IndexRangeContext):
        return self.visitChildren(ctx)


    # Visit a parse tree produced by AutolevParser#ident.
    def visitIdent(self, ctx:AutolevParser.IdentContext):
        return self.visitChildren(ctx)



del AutolevParser